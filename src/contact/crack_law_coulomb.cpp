// Coulomb friction between flat faces: the tangential spring k_t sticks until
// |T| = μN, then the faces slide: radial return onto the friction disk
// |T| ≤ μN (PHYSICS.md §3.5; with one tangential component the clamp of the 2D
// law, operation for operation). The dissipated energy of a step is the slip
// times the trapezoid mean of the friction force: second order in the step on a
// straight path, first order on a curved one (the MMD law is the exact one in 2D).
#include <cmath>
#include <stdexcept>
#include <string>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

class CoulombLaw final : public CrackLaw {
 public:
  CoulombLaw(std::unique_ptr<NormalLaw> law, double mu, double kt) : law_(std::move(law)), mu_(mu), kt_(kt) {}
  std::string name() const override { return "coulomb"; }
  void initialize(std::size_t cells, const double* a, const Tangential* b) override {
    cells_.resize(cells);
    for (std::size_t i = 0; i < cells; ++i) cells_[i] = {a[i], b[i], b[i]};
  }
  std::size_t cells() const override { return cells_.size(); }

  Traction trial(std::size_t cell, double a, const Tangential& b) const override {
    if (!(a > 0.0)) return {0.0, Tangential::zero(b.components())};
    const Cell& c = cells_[cell];
    const double N = law_->eval(a).N;
    return {N, onto_friction_disk(spring(b, contact_offset(c, a, b)), mu_ * N)};
  }

  StepResult commit(std::size_t cell, double a, const Tangential& b) override {
    Cell& c = cells_[cell];
    StepResult r;
    if (!(a > 0.0)) {
      c = {a, b, b};
      r.T = Tangential::zero(b.components());
      return r;
    }
    const double N1 = c.a > 0.0 ? law_->eval(c.a).N : 0.0;
    const Tangential b0_start = contact_offset(c, a, b);
    r.N = law_->eval(a).N;
    const Tangential T_trial = spring(b, b0_start);
    Tangential b0 = b0_start;
    r.state = ContactState::Stick;
    if (norm(T_trial) > mu_ * r.N) {
      const Tangential s = direction(T_trial);
      for (int k = 0; k < b.components(); ++k) b0[k] = b[k] - s[k] * mu_ * r.N / kt_;
      r.state = ContactState::Slide;
    }
    r.T = spring(b, b0);
    r.dW = mu_ * (N1 + r.N) * distance(b0, b0_start);
    c = {a, b, b0};
    return r;
  }

  double stored_energy(std::size_t cell) const override {
    const Cell& c = cells_[cell];
    if (!(c.a > 0.0)) return 0.0;
    const Tangential T = spring(c.b, c.b0);
    return 2.0 * law_->eval(c.a).M + dot(T, T) / kt_;
  }
  Tangential slip_offset(std::size_t cell) const override { return cells_[cell].b0; }
  CellStiffness stiffness(std::size_t, double a) const override {
    return {a > 0.0 ? law_->eval(a).dN : law_->stiffness_at_zero(), kt_};
  }
  bool can_dissipate() const override { return mu_ > 0.0; }
  double friction_bound() const override { return mu_; }
  bool has_contact() const override { return true; }
  std::vector<double> save_state(std::size_t c) const override {
    return save_cell_state({cells_[c].a}, {cells_[c].b, cells_[c].b0});
  }
  void restore_state(std::size_t c, const double* v, std::size_t n) override {
    restore_cell_state(v, n, {&cells_[c].a}, {&cells_[c].b, &cells_[c].b0});
  }

 private:
  struct Cell {
    double a;
    Tangential b, b0;
  };
  /// T = k_t (b − b0), component by component.
  Tangential spring(const Tangential& b, const Tangential& b0) const {
    Tangential T = b;
    for (int k = 0; k < b.components(); ++k) T[k] = kt_ * (b[k] - b0[k]);
    return T;
  }
  /// The trial traction returned radially onto |T| ≤ bound.
  static Tangential onto_friction_disk(const Tangential& T, double bound) {
    if (!(norm(T) > bound)) return T;
    const Tangential s = direction(T);
    Tangential on_disk = T;
    for (int k = 0; k < T.components(); ++k) on_disk[k] = s[k] * bound;
    return on_disk;
  }
  /// b0 at the start of a step ending at (a, b): when contact starts inside
  /// the step, the faces stick where they touched (a = 0 on the straight path).
  static Tangential contact_offset(const Cell& c, double a, const Tangential& b) {
    if (c.a > 0.0) return c.b0;
    Tangential touch = b;
    for (int k = 0; k < b.components(); ++k) touch[k] = c.b[k] + (0.0 - c.a) / (a - c.a) * (b[k] - c.b[k]);
    return touch;
  }

  std::unique_ptr<NormalLaw> law_;
  double mu_, kt_;
  std::vector<Cell> cells_;
};

}  // namespace

const ContactParameterList& coulomb_law_parameters() {
  static const ContactParameterList list = {
      real_parameter("-crack_coulomb_kt", &ContactParameters::coulomb_kt, "1e14", Range::positive(), "Pa/m",
                     "coulomb crack law: tangential stiffness k_t while the faces stick"),
  };
  return list;
}

std::unique_ptr<CrackLaw> create_coulomb_law(const ContactParameters& params) {
  return std::make_unique<CoulombLaw>(create_normal_law(params), params.mu, params.coulomb_kt);
}

}  // namespace vibrotherm::contact

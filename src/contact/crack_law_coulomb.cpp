// Coulomb friction between flat faces: the tangential spring k_t sticks until
// |T| = μN, then the faces slide (return mapping). The dissipated energy of a
// step is the slip times the trapezoid mean of the friction force: second
// order in the step (the MMD law is the exact one).
#include <algorithm>
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
  void initialize(std::size_t cells, const double* a, const double* b) override {
    cells_.resize(cells);
    for (std::size_t i = 0; i < cells; ++i) cells_[i] = {a[i], b[i], b[i]};
  }
  std::size_t cells() const override { return cells_.size(); }

  Traction trial(std::size_t cell, double a, double b) const override {
    if (!(a > 0.0)) return {};
    const Cell& c = cells_[cell];
    const double N = law_->eval(a).N;
    return {N, std::clamp(kt_ * (b - contact_offset(c, a, b)), -mu_ * N, mu_ * N)};
  }

  StepResult commit(std::size_t cell, double a, double b) override {
    Cell& c = cells_[cell];
    StepResult r;
    if (!(a > 0.0)) {
      c = {a, b, b};
      return r;
    }
    const double N1 = c.a > 0.0 ? law_->eval(c.a).N : 0.0;
    const double b0_start = contact_offset(c, a, b);
    r.N = law_->eval(a).N;
    const double T_trial = kt_ * (b - b0_start);
    double b0 = b0_start;
    r.state = ContactState::Stick;
    if (std::abs(T_trial) > mu_ * r.N) {
      const double s = T_trial > 0.0 ? 1.0 : -1.0;
      b0 = b - s * mu_ * r.N / kt_;
      r.state = ContactState::Slide;
    }
    r.T = kt_ * (b - b0);
    r.dW = mu_ * (N1 + r.N) * std::abs(b0 - b0_start);
    c = {a, b, b0};
    return r;
  }

  double stored_energy(std::size_t cell) const override {
    const Cell& c = cells_[cell];
    if (!(c.a > 0.0)) return 0.0;
    const double T = kt_ * (c.b - c.b0);
    return 2.0 * law_->eval(c.a).M + T * T / kt_;
  }
  double slip_offset(std::size_t cell) const override { return cells_[cell].b0; }
  CellStiffness stiffness(std::size_t, double a) const override {
    return {a > 0.0 ? law_->eval(a).dN : law_->stiffness_at_zero(), kt_};
  }
  bool can_dissipate() const override { return mu_ > 0.0; }
  double friction_bound() const override { return mu_; }
  bool has_contact() const override { return true; }
  std::vector<double> save_state(std::size_t c) const override { return {cells_[c].a, cells_[c].b, cells_[c].b0}; }
  void restore_state(std::size_t c, const double* v, std::size_t n) override {
    if (n != 3) throw std::runtime_error("coulomb crack law: a saved cell state has 3 values, not " + std::to_string(n));
    cells_[c] = {v[0], v[1], v[2]};
  }

 private:
  struct Cell {
    double a, b, b0;
  };
  /// b0 at the start of a step ending at (a, b): when contact starts inside
  /// the step, the faces stick where they touched (a = 0 on the straight path).
  static double contact_offset(const Cell& c, double a, double b) {
    if (c.a > 0.0) return c.b0;
    return c.b + (0.0 - c.a) / (a - c.a) * (b - c.b);
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

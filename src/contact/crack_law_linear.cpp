// Schoenberg's linear slip interface: N = k_n a and T = k_t b for both signs of
// a (the faces are glued by springs). In full-jump terms the interface
// stiffnesses per unit area are K_n = k_n/2 and K_t = k_t/2.
#include <limits>
#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {
namespace {

class LinearSlipLaw final : public CrackLaw {
 public:
  LinearSlipLaw(double kn, double kt) : kn_(kn), kt_(kt) {}
  std::string name() const override { return "linear"; }
  void initialize(std::size_t cells, const double* a, const Tangential* b) override {
    a_.assign(a, a + cells);
    b_.assign(b, b + cells);
  }
  std::size_t cells() const override { return a_.size(); }
  Traction trial(std::size_t, double a, const Tangential& b) const override { return {kn_ * a, spring(b)}; }
  StepResult commit(std::size_t cell, double a, const Tangential& b) override {
    a_[cell] = a;
    b_[cell] = b;
    return {kn_ * a, spring(b), 0.0, ContactState::Stick};
  }
  double stored_energy(std::size_t c) const override {
    double U = kn_ * a_[c] * a_[c];
    for (int k = 0; k < b_[c].components(); ++k) U += kt_ * b_[c][k] * b_[c][k];
    return U;
  }
  Tangential slip_offset(std::size_t c) const override { return Tangential::zero(b_[c].components()); }
  CellStiffness stiffness(std::size_t, double) const override { return {kn_, kt_}; }
  bool can_dissipate() const override { return false; }
  double friction_bound() const override { return std::numeric_limits<double>::infinity(); }
  bool has_contact() const override { return true; }

  std::vector<double> save_state(std::size_t c) const override { return save_cell_state({a_[c]}, {b_[c]}); }
  void restore_state(std::size_t c, const double* v, std::size_t n) override {
    restore_cell_state(v, n, {&a_[c]}, {&b_[c]});
  }

 private:
  /// T = k_t b, component by component.
  Tangential spring(const Tangential& b) const {
    Tangential T = b;
    for (int k = 0; k < b.components(); ++k) T[k] = kt_ * b[k];
    return T;
  }

  double kn_, kt_;
  std::vector<double> a_;
  std::vector<Tangential> b_;
};

}  // namespace

const ContactParameterList& linear_slip_law_parameters() {
  using P = ContactParameters;
  static const ContactParameterList list = {
      real_parameter("-crack_linear_kn", &P::linear_kn, "1e14", Range::positive(), "Pa/m",
                     "linear crack law: normal stiffness k_n in N = k_n a"),
      real_parameter("-crack_linear_kt", &P::linear_kt, "1e14", Range::positive(), "Pa/m",
                     "linear crack law: tangential stiffness k_t in T = k_t b"),
  };
  return list;
}

std::unique_ptr<CrackLaw> create_linear_slip_law(const ContactParameters& params) {
  return std::make_unique<LinearSlipLaw>(params.linear_kn, params.linear_kt);
}

}  // namespace vibrotherm::contact

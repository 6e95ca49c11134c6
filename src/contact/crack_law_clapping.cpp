// Clapping: the normal law alone, frictionless faces (T = 0, no dissipation).
#include <limits>
#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

class ClappingLaw final : public CrackLaw {
 public:
  explicit ClappingLaw(std::unique_ptr<NormalLaw> law) : law_(std::move(law)) {}
  std::string name() const override { return "clapping"; }
  void initialize(std::size_t cells, const double* a, const Tangential* b) override {
    a_.assign(a, a + cells);
    b_.assign(b, b + cells);
  }
  std::size_t cells() const override { return a_.size(); }
  Traction trial(std::size_t, double a, const Tangential& b) const override {
    return {law_->eval(a).N, Tangential::zero(b.components())};
  }
  StepResult commit(std::size_t cell, double a, const Tangential& b) override {
    a_[cell] = a;
    b_[cell] = b;
    return {law_->eval(a).N, Tangential::zero(b.components()), 0.0,
            a > 0.0 ? ContactState::Slide : ContactState::Loss};
  }
  double stored_energy(std::size_t c) const override { return 2.0 * law_->eval(a_[c]).M; }
  Tangential slip_offset(std::size_t c) const override { return b_[c]; }
  CellStiffness stiffness(std::size_t, double a) const override {
    return {a > 0.0 ? law_->eval(a).dN : law_->stiffness_at_zero(), 0.0};
  }
  bool can_dissipate() const override { return false; }
  double friction_bound() const override { return std::numeric_limits<double>::infinity(); }
  bool has_contact() const override { return true; }

  std::vector<double> save_state(std::size_t c) const override { return save_cell_state({a_[c]}, {b_[c]}); }
  void restore_state(std::size_t c, const double* v, std::size_t n) override {
    restore_cell_state(v, n, {&a_[c]}, {&b_[c]});
  }

 private:
  std::unique_ptr<NormalLaw> law_;
  std::vector<double> a_;
  std::vector<Tangential> b_;
};

}  // namespace

std::unique_ptr<CrackLaw> create_clapping_law(const ContactParameters& params) {
  return std::make_unique<ClappingLaw>(create_normal_law(params));
}

}  // namespace vibrotherm::contact

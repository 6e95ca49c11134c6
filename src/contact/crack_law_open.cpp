// Open crack: the faces never touch, tractions are zero.
#include <limits>
#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {
namespace {

class OpenLaw final : public CrackLaw {
 public:
  std::string name() const override { return "open"; }
  void initialize(std::size_t cells, const double*, const Tangential* b) override { b_.assign(b, b + cells); }
  std::size_t cells() const override { return b_.size(); }
  Traction trial(std::size_t, double, const Tangential& b) const override {
    return {0.0, Tangential::zero(b.components())};
  }
  StepResult commit(std::size_t cell, double, const Tangential& b) override {
    b_[cell] = b;
    StepResult r;
    r.T = Tangential::zero(b.components());
    return r;
  }
  double stored_energy(std::size_t) const override { return 0.0; }
  Tangential slip_offset(std::size_t cell) const override { return b_[cell]; }
  CellStiffness stiffness(std::size_t, double) const override { return {}; }
  bool can_dissipate() const override { return false; }
  double friction_bound() const override { return std::numeric_limits<double>::infinity(); }
  bool has_contact() const override { return false; }

  std::vector<double> save_state(std::size_t c) const override { return save_cell_state({}, {b_[c]}); }
  void restore_state(std::size_t c, const double* v, std::size_t n) override { restore_cell_state(v, n, {}, {&b_[c]}); }

 private:
  std::vector<Tangential> b_;  // the faces slide freely: b0 follows b
};

}  // namespace

std::unique_ptr<CrackLaw> create_open_law(const ContactParameters&) { return std::make_unique<OpenLaw>(); }

}  // namespace vibrotherm::contact

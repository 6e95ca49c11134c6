// Open crack: the faces never touch, tractions are zero.
#include <limits>
#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {
namespace {

class OpenLaw final : public CrackLaw {
 public:
  std::string name() const override { return "open"; }
  void initialize(std::size_t cells, const double*, const double* b) override { b_.assign(b, b + cells); }
  std::size_t cells() const override { return b_.size(); }
  Traction trial(std::size_t, double, double) const override { return {}; }
  StepResult commit(std::size_t cell, double, double b) override {
    b_[cell] = b;
    return {};
  }
  double stored_energy(std::size_t) const override { return 0.0; }
  double slip_offset(std::size_t cell) const override { return b_[cell]; }
  CellStiffness stiffness(std::size_t, double) const override { return {}; }
  bool can_dissipate() const override { return false; }
  double friction_bound() const override { return std::numeric_limits<double>::infinity(); }
  bool has_contact() const override { return false; }

  std::vector<double> save_state(std::size_t c) const override { return save_cell_values(c, {&b_}); }
  void restore_state(std::size_t c, const double* v, std::size_t n) override { restore_cell_values(c, v, n, {&b_}); }

 private:
  std::vector<double> b_;  // the faces slide freely: b0 follows b
};

}  // namespace

std::unique_ptr<CrackLaw> create_open_law(const ContactParameters&) { return std::make_unique<OpenLaw>(); }

}  // namespace vibrotherm::contact

// Linear law N = k a (a > 0): a flat contact; all stiffness sits at first touch.
#include <cmath>

#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

class LinearLaw final : public NormalLaw {
 public:
  explicit LinearLaw(double k) : k_(k) {}
  NormalLawValue eval(double a) const override {
    if (!(a > 0.0)) return {};
    return {k_ * a, k_, 0.5 * k_ * a * a};
  }
  double stiffness_at_zero() const override { return k_; }
  std::string name() const override { return "linear"; }

 private:
  double k_;
};

}  // namespace

std::unique_ptr<NormalLaw> create_linear_law(const ContactParameters& params) {
  if (!(params.normal_k > 0.0) || !std::isfinite(params.normal_k))
    throw InputError("-contact_normal_k must be > 0 for the linear law");
  return std::make_unique<LinearLaw>(params.normal_k);
}

}  // namespace vibrotherm::contact

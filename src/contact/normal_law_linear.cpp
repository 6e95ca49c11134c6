// Linear law N = k a (a > 0): a flat contact; all stiffness sits at first touch.
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
  /// N'' = 0 for a > 0: the whole bed is the atom at α = 0.
  DensityMoments density_moments(double, const NormalLawValue&, double, const NormalLawValue&) const override {
    return {};
  }
  std::string name() const override { return "linear"; }

 private:
  double k_;
};

}  // namespace

const ContactParameterList& linear_law_parameters() {
  static const ContactParameterList list = {
      real_parameter("-contact_linear_k", &ContactParameters::linear_k, "1e14", Range::positive(), "Pa/m",
                     "linear normal law: k in N = k a"),
  };
  return list;
}

std::unique_ptr<NormalLaw> create_linear_law(const ContactParameters& params) {
  return std::make_unique<LinearLaw>(params.linear_k);
}

}  // namespace vibrotherm::contact

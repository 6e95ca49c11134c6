// Power law N = C a^p (p >= 1). Hertz contact of a sphere: p = 3/2.
#include <cmath>
#include <sstream>

#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

class PowerLaw final : public NormalLaw {
 public:
  PowerLaw(double C, double p, std::string name) : C_(C), p_(p), name_(std::move(name)) {}

  NormalLawValue eval(double a) const override {
    if (!(a > 0.0)) return {};
    // One pow gives all three: N' = pN/a, M = Na/(p+1).
    const double N = C_ * std::pow(a, p_);
    return {N, p_ * N / a, N * a / (p_ + 1.0)};
  }
  double stiffness_at_zero() const override { return p_ == 1.0 ? C_ : 0.0; }
  std::string name() const override { return name_; }

 private:
  double C_, p_;
  std::string name_;
};

}  // namespace

std::unique_ptr<NormalLaw> make_power_law(double C, double p, std::string name) {
  return std::make_unique<PowerLaw>(C, p, std::move(name));
}

std::unique_ptr<NormalLaw> create_power_law(const ContactParameters& params) {
  // Default C: N(10 nm) = 1 MPa with the Hertz exponent, the order of Al-Al contacts.
  const double C = params.normal_C < 0.0 ? 1e18 : params.normal_C;
  if (!(C > 0.0) || !std::isfinite(C)) throw InputError("-contact_normal_C must be > 0 for the power law");
  if (!(params.normal_p >= 1.0) || !std::isfinite(params.normal_p)) {
    std::ostringstream msg;
    msg << "-contact_normal_p must be >= 1 (a convex law), got " << params.normal_p;
    throw InputError(msg.str());
  }
  return make_power_law(C, params.normal_p, "power");
}

}  // namespace vibrotherm::contact

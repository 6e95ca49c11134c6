// Power law N = C a^p (p >= 1). Hertz contact of a sphere: p = 3/2.
#include <cmath>

#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

class PowerLaw final : public NormalLaw {
 public:
  PowerLaw(double C, double p, std::string name)
      : C_(C), p_(p), name_(std::move(name)),
        shape_(p == 1.0 ? Shape::Linear : p == 1.5 ? Shape::Hertz : p == 2.0 ? Shape::Quadratic : Shape::General) {}

  NormalLawValue eval(double a) const override {
    if (!(a > 0.0)) return {};
    // One power gives all three: N' = pN/a, M = Na/(p+1). The exponents of the
    // default laws (Biwa m = 1/2: p = 2; Hertz: p = 3/2) avoid pow(), the hot
    // spot of the MMD update.
    double ap;
    switch (shape_) {
      case Shape::Linear: ap = a; break;
      case Shape::Hertz: ap = a * std::sqrt(a); break;
      case Shape::Quadratic: ap = a * a; break;
      default: ap = std::pow(a, p_);
    }
    const double N = C_ * ap;
    return {N, p_ * N / a, N * a / (p_ + 1.0)};
  }
  double stiffness_at_zero() const override { return p_ == 1.0 ? C_ : 0.0; }
  DensityMoments density_moments(double x, const NormalLawValue& at_x, double y,
                                 const NormalLawValue& at_y) const override;
  std::string name() const override { return name_; }

 private:
  enum class Shape { Linear, Hertz, Quadratic, General };
  double C_, p_;
  std::string name_;
  Shape shape_;
};

/// On an interval short against x, N''(x + u) = N''(x) (1 + u/x)^(p−2) as a binomial series:
/// m_k = N''(x) d^(k+1) Σ_j C(p−2, j) h^j / (k + 1 + j), h = d/x <= kShort. Twelve terms keep
/// ~1e-19 of the sum there; the values at x give N'' = p(p−1)N/x² without a pow().
DensityMoments PowerLaw::density_moments(double x, const NormalLawValue& at_x, double y,
                                         const NormalLawValue& at_y) const {
  constexpr double kShort = 1e-2;
  constexpr int kTerms = 12;
  const double d = y - x;
  if (shape_ == Shape::Linear) return {};  // N'' = 0: all stiffness sits in the atom at 0
  if (!(x > 0.0) || !(d < kShort * x)) return NormalLaw::density_moments(x, at_x, y, at_y);
  const double h = d / x, ddN = p_ * (p_ - 1.0) * at_x.N / (x * x);
  double sums[3] = {0.0, 0.0, 0.0}, coefficient = 1.0, power = 1.0;  // C(p−2, j), h^j
  for (int j = 0; j < kTerms; ++j) {
    for (int k = 0; k < 3; ++k) sums[k] += coefficient * power / (k + 1 + j);
    coefficient *= (p_ - 2.0 - j) / (j + 1.0);
    power *= h;
  }
  return {ddN * d * sums[0], ddN * d * d * sums[1], ddN * d * d * d * sums[2]};
}

}  // namespace

std::unique_ptr<NormalLaw> make_power_law(double C, double p, std::string name) {
  return std::make_unique<PowerLaw>(C, p, std::move(name));
}

const ContactParameterList& power_law_parameters() {
  using P = ContactParameters;
  // Default C: N(10 nm) = 1 MPa with the Hertz exponent, the order of Al-Al
  // contacts. p >= 1 keeps the law convex; beyond 10, a^p underflows for
  // approaches of nanometres.
  static const ContactParameterList list = {
      real_parameter("-contact_power_C", &P::power_C, "1e18", Range::positive(), "Pa/m^p",
                     "power law: C in N = C a^p"),
      real_parameter("-contact_power_p", &P::power_p, "1.5", Range::between(1.0, 10.0), "",
                     "power law: exponent p in N = C a^p (Hertz: 3/2)"),
  };
  return list;
}

std::unique_ptr<NormalLaw> create_power_law(const ContactParameters& params) {
  return make_power_law(params.power_C, params.power_p, "power");
}

}  // namespace vibrotherm::contact

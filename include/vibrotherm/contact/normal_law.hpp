// Normal contact laws N(a) for rough crack faces (PHYSICS.md §3.2).
//
// a is the half normal approach (a > 0: faces pressed together), N the
// compressive normal traction. Every law is convex and increasing for a > 0 and
// zero for a <= 0. The memory-diagram algorithm needs, at any abscissa a:
//   N(a), N'(a) and M(a) = ∫_0^a N(α) dα
// (M gives the exact dissipated and stored energies in closed form), plus the
// stiffness at first touch N'(0+), which is the weight of the spring at α = 0
// in the spring-bed picture (non-zero for flat/linear laws).
//
// The dissipation integrals need the moments of the spring-bed density N'' on
// an interval, to full relative precision however short the interval: a
// pre-loaded contact that barely moves slips only in a sliver of width
// ~1e-16·a below its apex, where N, N', M all agree to the last digit and their
// differences would keep none (issue 23: rounding then dissipated 1e-9 J/m²).
#pragma once

#include <memory>
#include <string>

namespace vibrotherm::contact {

/// The three values of a normal law at one abscissa, computed together
/// (for power laws one pow() gives all three).
struct NormalLawValue {
  double N = 0.0;   ///< normal traction N(a) [Pa]
  double dN = 0.0;  ///< N'(a) [Pa/m]
  double M = 0.0;   ///< ∫_0^a N [Pa m]
};

/// Moments of the spring-bed density on (x, y]: m_k = ∫_x^y (α − x)^k N''(α) dα.
/// The atom N'(0+) at α = 0 is not part of them.
struct DensityMoments {
  double m0 = 0.0, m1 = 0.0, m2 = 0.0;
};

class NormalLaw {
 public:
  virtual ~NormalLaw() = default;
  /// N, N', M at a; all zero for a <= 0.
  virtual NormalLawValue eval(double a) const = 0;
  /// lim_{a→0+} N'(a): the stiffness of the contact at first touch.
  virtual double stiffness_at_zero() const = 0;
  /// The moments of N'' on (x, y], 0 <= x <= y, given the law's values at both
  /// ends; accurate relative to the moments themselves for any y − x. This
  /// default takes differences of the values, which keep only ~(y − x)²/x² of
  /// the digits of m2: laws override it where short intervals occur.
  virtual DensityMoments density_moments(double x, const NormalLawValue& at_x, double y,
                                         const NormalLawValue& at_y) const;
  /// Registry name of the law ("power", "biwa", ...).
  virtual std::string name() const = 0;
};

}  // namespace vibrotherm::contact

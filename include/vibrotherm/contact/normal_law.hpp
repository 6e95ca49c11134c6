// Normal contact laws N(a) for rough crack faces (PHYSICS.md §3.2).
//
// a is the half normal approach (a > 0: faces pressed together), N the
// compressive normal traction. Every law is convex and increasing for a > 0 and
// zero for a <= 0. The memory-diagram algorithm needs, at any abscissa a:
//   N(a), N'(a) and M(a) = ∫_0^a N(α) dα
// (M gives the exact dissipated and stored energies in closed form), plus the
// stiffness at first touch N'(0+), which is the weight of the spring at α = 0
// in the spring-bed picture (non-zero for flat/linear laws).
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

class NormalLaw {
 public:
  virtual ~NormalLaw() = default;
  /// N, N', M at a; all zero for a <= 0.
  virtual NormalLawValue eval(double a) const = 0;
  /// lim_{a→0+} N'(a): the stiffness of the contact at first touch.
  virtual double stiffness_at_zero() const = 0;
  /// Registry name of the law ("power", "biwa", ...).
  virtual std::string name() const = 0;
};

}  // namespace vibrotherm::contact

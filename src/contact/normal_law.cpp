// The default moments of the spring-bed density: differences of N', N and M.
#include "vibrotherm/contact/normal_law.hpp"

namespace vibrotherm::contact {

DensityMoments NormalLaw::density_moments(double x, const NormalLawValue& at_x, double y,
                                          const NormalLawValue& at_y) const {
  // Integration by parts about x: m0 = ΔN', m1 = Δ N'_y − ΔN, m2 = Δ² N'_y − 2Δ N_y + 2ΔM (Δ = y − x,
  // differences of M and N taken against their Taylor terms at x). At x = 0 the atom N'(0+) is excluded.
  const double d = y - x;
  const double dN_x = x > 0.0 ? at_x.dN : stiffness_at_zero();
  const double rN = at_y.N - at_x.N - dN_x * d;                          // ∫ (y − α) N'' dα
  const double rM = at_y.M - at_x.M - at_x.N * d - 0.5 * dN_x * d * d;  // ∫ (y − α)²/2 N'' dα
  DensityMoments m;
  m.m0 = at_y.dN - dN_x;
  m.m1 = d * m.m0 - rN;               // ∫ (α − x) N'' = ∫ (d − (y − α)) N''
  m.m2 = d * d * m.m0 - 2.0 * d * rN + 2.0 * rM;  // ∫ (d − (y − α))² N''
  return m;
}

}  // namespace vibrotherm::contact

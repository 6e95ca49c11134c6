// A force on the bulk that the wave solver does not own, affine in u:
//   f(t, u) = g(t) − S u,   S symmetric positive semidefinite,
// e.g. the thermal stress of the heat field (coupling/thermal_stress.hpp). The
// solver adds M⁻¹ f to every acceleration (before the boundary terms, so the
// supports' reactions include it), includes a bound of M⁻¹S in its stable step,
// and accounts the force's work f·Δu per step: exact for velocity Verlet, whose
// kick applies f at the step's midpoint and whose drift moves u by h v̄ (other
// explicit types: the trapezoidal rule, to their order).
#pragma once

#include <petscvec.h>

namespace vibrotherm::wave {

class BodyForce {
 public:
  virtual ~BodyForce() = default;
  /// f = f(t, u) (a force, not mass-scaled; global vectors of the wave DM).
  virtual PetscErrorCode Force(double t, Vec u, Vec f) = 0;
  /// An upper bound of the largest eigenvalue of M⁻¹S [rad²/s²] (M the lumped mass).
  virtual PetscErrorCode MaxFrequencySquared(Vec mass, double* omega2) const = 0;
  /// Its name in messages.
  virtual const char* name() const = 0;
};

}  // namespace vibrotherm::wave

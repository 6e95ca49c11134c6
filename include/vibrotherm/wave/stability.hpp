// The explicit stability limit dt < (ω dt)_max / ω_max:
//   ω_max  from SLEPc: largest eigenvalue of M^{-1/2} K M^{-1/2} (symmetric,
//          same spectrum as M^{-1}K), square-rooted;
//   (ω dt)_max of the chosen TS type, measured on the oscillator u'' = -u
//          integrated by a TS configured exactly like the wave TS (same prefix
//          and options): the largest ω dt whose solution does not grow.
//          Velocity Verlet: 2; RK4: 2√2; methods without the imaginary axis
//          in their stability region: ~0.
#pragma once

#include <petscmat.h>
#include <petscts.h>

namespace vibrotherm::wave {

PetscErrorCode LargestAngularFrequency(Mat K, Vec lumped_mass, double* omega_max);

/// (ω dt)_max of the TS type selected by the options under `prefix`; 0 and
/// implicit = true for implicit types (no stability limit).
PetscErrorCode OscillatorStabilityLimit(const char* prefix, double* omega_dt_max, bool* implicit);

}  // namespace vibrotherm::wave

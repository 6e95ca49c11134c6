// The source on the labelled source edge (PHYSICS.md §2):
//   g(t) = A sin(2π f t) w(t)
// with a smooth window w: sin² switch-on over -source_ramp_cycles cycles,
// plateau, cos² switch-off ending at -source_duration, zero after.
// A displacement source prescribes the chosen component (tangential or normal
// to the edge) and leaves the other free; a traction source applies g(t) [Pa]
// along that direction.
#pragma once

#include <petscsys.h>

namespace vibrotherm::wave {

enum class SourceType { Displacement, Traction };
enum class SourceComponent { Tangential, Normal };

struct SourceTimeFunction {
  double amplitude = 1e-7;    ///< [m] (displacement) or [Pa] (traction)
  double frequency = 1e5;     ///< [Hz]
  double duration = 1e-3;     ///< [s]
  double ramp_cycles = 3.0;   ///< cycles of switch-on and of switch-off

  /// g, dg/dt, d²g/dt² at time t.
  void evaluate(double t, double* g, double* dg, double* ddg) const;
};

struct Excitation {
  SourceType type = SourceType::Displacement;
  SourceComponent component = SourceComponent::Tangential;
  SourceTimeFunction signal;
};

/// -source_type, -source_component, -source_frequency, -source_amplitude,
/// -source_duration, -source_ramp_cycles.
PetscErrorCode ReadExcitation(MPI_Comm comm, Excitation* excitation);

}  // namespace vibrotherm::wave

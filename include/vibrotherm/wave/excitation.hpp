// The source on the labelled source edge (PHYSICS.md §2):
//   g(t) = A(t) sin(2π f t) w(t)
// with a smooth window w: sin² switch-on over -source_ramp_cycles cycles,
// plateau, cos² switch-off ending at -source_duration, zero after; and an
// amplitude A(t) = -source_amplitude, stepped by -source_schedule t1,A1,t2,A2,...
// (from t_i on A_i, reached by a sin² blend over max(ramp, one period)).
// Between those changes the source is periodic: its steady stretches.
// -source_sweep F1,F2 instead makes the frequency run linearly from F1 to F2 over
// the source duration (a chirp, Rahammer et al. 2017): g(t) = A sin(2π c(t)) w(t)
// with c(t) = F1 t + (F2 − F1) t² / (2 T) the cycles so far; a sweep never repeats
// (no steady stretch). Its switch-on and -off last -source_ramp_cycles cycles of the
// lower frequency.
// A displacement source prescribes the chosen component (tangential or normal
// to the edge) and leaves the other free; a traction source applies g(t) [Pa]
// along that direction.
#pragma once

#include <petscsys.h>

#include <vector>

#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::wave {

enum class SourceType { Displacement, Traction };
enum class SourceComponent { Tangential, Normal };

struct SourceTimeFunction {
  double amplitude = 1e-7;    ///< [m] (displacement) or [Pa] (traction)
  double frequency = 1e5;     ///< [Hz]
  double duration = 1e-3;     ///< [s]
  double ramp_cycles = 3.0;   ///< cycles of switch-on and of switch-off
  struct Step {
    double t, amplitude;  ///< from t on, this amplitude (after the blend)
  };
  std::vector<Step> schedule;  ///< -source_schedule, by time
  bool running_at_start = false;  ///< no switch-on: the waves start in the source's steady response
  double sweep_from = 0.0, sweep_to = 0.0;  ///< -source_sweep F1,F2 [Hz] (0: no sweep; frequency = max of both)

  bool sweeping() const { return sweep_from > 0.0; }
  /// Source cycles completed by time t (the phase over 2π): f t, or the sweep's c(t).
  double cycles(double t) const;
  /// The instantaneous frequency dc/dt at t [Hz].
  double frequency_at(double t) const;
  /// The time at which `cycles` cycles are complete (the inverse of cycles()).
  double time_of_cycle(double cycles) const;

  /// g, dg/dt, d²g/dt² at time t.
  void evaluate(double t, double* g, double* dg, double* ddg) const;
  /// The switch-on/off window w(t) and its derivatives (0 outside the source's duration).
  void window(double t, double* win, double* dwin, double* ddwin) const;
  /// The amplitude at t with its window and schedule: A(t) w(t) (g's envelope).
  double envelope(double t) const;
  double ramp_time() const;   ///< length of the switch-on and of the switch-off [s]
  double blend_time() const;  ///< length of a schedule step's blend [s]
  /// The steady stretch (constant amplitude, no ramp) holding t: [*start, *end]; false outside any.
  bool steady_stretch(double t, double* start, double* end) const;
};

struct Excitation {
  SourceType type = SourceType::Displacement;
  SourceComponent component = SourceComponent::Tangential;
  SourceTimeFunction signal;
};

/// The source's options as typed: the schedule and the sweep are lists until checked against
/// the signal they shape.
struct ExcitationOptions {
  Excitation excitation;
  std::vector<double> schedule;  ///< -source_schedule t1,A1,t2,A2,...
  std::vector<double> sweep;     ///< -source_sweep F1,F2 [Hz]
};
/// -source_type, -source_component, -source_frequency, -source_amplitude, -source_duration,
/// -source_ramp_cycles, -source_schedule, -source_sweep, declared (option_spec.hpp).
const std::vector<OptionSpec<ExcitationOptions>>& ExcitationOptionSpecs();
/// Reads them into excitation (its values are the defaults). Collective.
PetscErrorCode ReadExcitation(MPI_Comm comm, Excitation* excitation, OptionValues* values = nullptr);

}  // namespace vibrotherm::wave

// Periodic continuation's options (-periodic*; periodic_continuation.hpp).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::coupling {

/// -periodic auto|on|off: auto continues when heat runs (the continuation feeds the heat;
/// without it, continuing would only skip the waves a wave-only run is for).
enum class PeriodicChoice { Auto, On, Off };

struct PeriodicOptions {
  PeriodicChoice choice = PeriodicChoice::Auto;
  bool on = true;             ///< choice is not off, and the coupling can compare whole periods
  double tol = 3e-4;          ///< -periodic_tol: largest change per period of the state and energies
  /// -periodic_tol_cells: largest change of the contact cell by cell (memory, friction energy's
  /// distribution: it wanders by ~0.4 % from window to window in the paper scene while the total
  /// repeats to 1e-5)
  double tol_cells = 1e-2;
  PetscInt max_multiple = 4;  ///< -periodic_max_multiple: longest period sought, in source periods
  /// -periodic_window: periods (of the period found) whose friction energy is compared with the
  /// window before, recorded and replayed as one: the contact's period-to-period noise averages out
  PetscInt window = 4;
  double refresh = 0.0;       ///< -periodic_refresh [s]: waves re-run after this much continuation (0: never)
  PetscInt ladder_steps = 16;  ///< -periodic_ladder_steps: heat steps per rung (the step doubles after them)
  PetscInt fine_periods = 4;   ///< -periodic_fine_periods: phase-resolved heat periods before the ladder
  PetscInt min_continued = 8;  ///< -periodic_min_continued: fewer periods to skip are simply simulated
  /// -periodic_drift_tol: a continuation freezes the friction per period it recorded; while that still
  /// drifts (a ratcheting crack), half the drift over the continuation, relative, is what the frozen
  /// heat would miss if the drift went on. Above this the waves run on (0: measured and reported only)
  double drift_tol = 0.0;
  /// -periodic_mode state|mean: state (the waves and the contact repeat period by period), or
  /// mean: a statistically steady state (a clapping crack can be chaotic: no two periods alike,
  /// yet every window of -periodic_window periods takes the same friction, damping and work):
  /// only the windows' energies and the cells' friction per window are compared, against
  /// -periodic_tol, and the window recorded is replayed as the mean heat (periodic_detector.hpp)
  bool mean = false;
  /// -periodic_save_state FILE: where the waves are suspended (a period boundary of the steady
  /// state), their state is saved there: another run at the same frequency can begin in it
  /// (-wave_start state; saved_wave_state.hpp)
  std::string save_state;
};

/// The -periodic* options, declared (option_spec.hpp): name, help, unit, range, field.
const std::vector<OptionSpec<PeriodicOptions>>& PeriodicOptionSpecs();
/// Reads -periodic*, checked, named errors. Collective.
PetscErrorCode ReadPeriodicOptions(MPI_Comm comm, PeriodicOptions* options, OptionValues* values = nullptr);

}  // namespace vibrotherm::coupling

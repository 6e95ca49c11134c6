#include "vibrotherm/coupling/continuation/periodic_options.hpp"

namespace vibrotherm::coupling {

const std::vector<OptionSpec<PeriodicOptions>>& PeriodicOptionSpecs() {
  using O = PeriodicOptions;
  using contact::Range;
  static const std::vector<OptionSpec<O>> specs = {
      ChoiceOption("-periodic", &O::choice, {"auto", "on", "off"},
                   "Once waves and contact repeat from period to period, suspend the waves and feed the heat the "
                   "recorded period until the source changes: auto (when heat runs), on, off"),
      RealOption("-periodic_tol", &O::tol, Range::open(0.0, 1.0), "",
                 "Periodic when the state, every cell's friction energy and the energy accounts change by less than "
                 "this from one period to the next"),
      RealOption("-periodic_tol_cells", &O::tol_cells, Range::open(0.0, 1.0), "",
                 "Periodic when, besides, the contact cell by cell (tractions and slip offsets, friction energy over "
                 "a window) changes by less than this"),
      IntOption("-periodic_max_multiple", &O::max_multiple, Range::between(1, 16),
                "Longest period sought, in source periods (clapping can halve the frequency)"),
      IntOption("-periodic_window", &O::window, Range::between(1, 64),
                "Periods (of the period found) compared as one window, recorded and replayed as one (the contact's "
                "period-to-period noise averages out)"),
      RealOption("-periodic_refresh", &O::refresh, Range::at_least(0.0), "s",
                 "Simulated time of continuation after which the waves run again and periodicity is checked anew "
                 "(0: only when the source changes)"),
      IntOption("-periodic_ladder_steps", &O::ladder_steps, Range::at_least(1),
                "Heat steps per rung of the continuation's step ladder (the step doubles after them)"),
      IntOption("-periodic_fine_periods", &O::fine_periods, Range::at_least(1),
                "Periods of phase-resolved heat steps at the start of a continuation (they give the crack's periodic "
                "near field)"),
      IntOption("-periodic_min_continued", &O::min_continued, Range::at_least(1),
                "A continuation shorter than this many periods is simulated instead"),
      RealOption("-periodic_drift_tol", &O::drift_tol, Range::closed_open(0.0, 1.0), "",
                 "Largest projected error of a continuation from the measured drift of the friction per period (half "
                 "the drift over the periods continued); above it the waves run on (0: report the drift only)"),
      ChoiceOption("-periodic_mode", &O::mean, {"state", "mean"},
                   "What repeats: state (waves and contact period by period) or mean (a statistically steady state: "
                   "the windows' friction, damping and work)"),
      TextOption("-periodic_save_state", &O::save_state,
                 "Save the wave state where the waves are suspended (a period boundary of the steady state) to this "
                 "file: another run at the same frequency can begin in it (-wave_start state)"),
  };
  return specs;
}

PetscErrorCode ReadPeriodicOptions(MPI_Comm comm, PeriodicOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Periodic continuation of a periodic source", PeriodicOptionSpecs(), o, values));
  o->on = o->choice != PeriodicChoice::Off;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

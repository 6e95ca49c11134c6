#include "vibrotherm/coupling/continuation/periodic_options.hpp"

#include <cmath>

#include "vibrotherm/options/petsc/option_choice.hpp"

namespace vibrotherm::coupling {

PetscErrorCode ReadPeriodicOptions(MPI_Comm comm, PeriodicOptions* o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Periodic continuation of a periodic source", nullptr);
  PetscCall(OptionsChoiceEnum(PetscOptionsObject, "-periodic",
                              "Once waves and contact repeat from period to period, suspend the waves and feed the heat "
                              "the recorded period until the source changes: auto (when heat runs), on, off",
                              {"auto", "on", "off"}, &o->choice));
  PetscCall(PetscOptionsReal("-periodic_tol", "Periodic when the state, every cell's friction energy and the energy "
                             "accounts change by less than this from one period to the next", nullptr, o->tol, &o->tol,
                             nullptr));
  PetscCall(PetscOptionsReal("-periodic_tol_cells", "Periodic when, besides, the contact cell by cell (tractions and slip "
                             "offsets, friction energy over a window) changes by less than this", nullptr,
                             o->tol_cells, &o->tol_cells, nullptr));
  PetscCall(PetscOptionsInt("-periodic_max_multiple", "Longest period sought, in source periods (clapping can halve "
                            "the frequency)", nullptr, o->max_multiple, &o->max_multiple, nullptr));
  PetscCall(PetscOptionsInt("-periodic_window", "Periods (of the period found) compared as one window, recorded and "
                            "replayed as one (the contact's period-to-period noise averages out)", nullptr, o->window,
                            &o->window, nullptr));
  PetscCall(PetscOptionsReal("-periodic_refresh", "Simulated seconds of continuation after which the waves run again "
                             "and periodicity is checked anew (0: only when the source changes)", nullptr, o->refresh,
                             &o->refresh, nullptr));
  PetscCall(PetscOptionsInt("-periodic_ladder_steps", "Heat steps per rung of the continuation's step ladder (the step "
                            "doubles after them)", nullptr, o->ladder_steps, &o->ladder_steps, nullptr));
  PetscCall(PetscOptionsInt("-periodic_fine_periods", "Periods of phase-resolved heat steps at the start of a "
                            "continuation (they give the crack's periodic near field)", nullptr, o->fine_periods,
                            &o->fine_periods, nullptr));
  PetscCall(PetscOptionsInt("-periodic_min_continued", "A continuation shorter than this many periods is simulated "
                            "instead", nullptr, o->min_continued, &o->min_continued, nullptr));
  PetscCall(PetscOptionsReal("-periodic_drift_tol", "Largest projected error of a continuation from the measured drift "
                             "of the friction per period (half the drift over the periods continued); above it the waves "
                             "run on (0: report the drift only)", nullptr, o->drift_tol, &o->drift_tol, nullptr));
  PetscInt mode = o->mean ? 1 : 0;
  PetscCall(OptionsChoice(PetscOptionsObject, "-periodic_mode",
                          "What repeats: state (waves and contact period by period) or mean (a statistically steady "
                          "state: the windows' friction, damping and work)", {"state", "mean"}, &mode, nullptr));
  o->mean = mode == 1;
  PetscOptionsEnd();
  o->on = o->choice != PeriodicChoice::Off;
  PetscCheck(o->tol > 0.0 && o->tol < 1.0, comm, PETSC_ERR_USER_INPUT, "-periodic_tol must be in (0, 1), got %g", o->tol);
  PetscCheck(o->max_multiple >= 1 && o->max_multiple <= 16, comm, PETSC_ERR_USER_INPUT,
             "-periodic_max_multiple must be in [1, 16], got %" PetscInt_FMT, o->max_multiple);
  PetscCheck(o->tol_cells > 0.0 && o->tol_cells < 1.0, comm, PETSC_ERR_USER_INPUT,
             "-periodic_tol_cells must be in (0, 1), got %g", o->tol_cells);
  PetscCheck(o->window >= 1 && o->window <= 64, comm, PETSC_ERR_USER_INPUT,
             "-periodic_window must be in [1, 64], got %" PetscInt_FMT, o->window);
  PetscCheck(o->refresh >= 0.0 && std::isfinite(o->refresh), comm, PETSC_ERR_USER_INPUT,
             "-periodic_refresh must be >= 0, got %g", o->refresh);
  PetscCheck(o->drift_tol >= 0.0 && o->drift_tol < 1.0, comm, PETSC_ERR_USER_INPUT,
             "-periodic_drift_tol must be in [0, 1), got %g", o->drift_tol);
  PetscCheck(o->ladder_steps >= 1, comm, PETSC_ERR_USER_INPUT, "-periodic_ladder_steps must be >= 1, got %" PetscInt_FMT,
             o->ladder_steps);
  PetscCheck(o->fine_periods >= 1, comm, PETSC_ERR_USER_INPUT, "-periodic_fine_periods must be >= 1, got %" PetscInt_FMT,
             o->fine_periods);
  PetscCheck(o->min_continued >= 1, comm, PETSC_ERR_USER_INPUT,
             "-periodic_min_continued must be >= 1, got %" PetscInt_FMT, o->min_continued);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

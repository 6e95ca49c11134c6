// -heat_free_ts_adapt_type ladder: a TSAdapt of vibrotherm's own for free
// diffusion (the heat TS once the waves are gone). The step stays on a rung for
// -heat_free_ts_adapt_ladder_steps steps, then grows by
// -heat_free_ts_adapt_ladder_ratio, starting from the rung StepLadderStart gives
// (the heat solver: its last coupled step), else from the TS's first step.
//
// Why not error control: after the sources stop the rise varies on the time
// since they stopped, so steps growing geometrically with t follow it, and a
// step that repeats keeps the Jacobian (K + M/(θh)) and its Cholesky factor:
// one factorisation per rung instead of one per step (the paper scene's free
// phase: 157 factorisations, 12 ms each, with the basic adaptor). The schedule
// depends on nothing computed, so 1 and N ranks take the very same steps (an
// error-controlled step, rounded to a ladder, flips between rungs on rounding).
// Steps are clipped to hit output times (TS matchstep: the stretch before a stop
// may be split in two halves, each a factorisation) and to
// -heat_free_ts_adapt_dt_min/max; the rung itself is kept across TSSolve calls
// (it grows no further than dt_max).
#pragma once

#include <petscts.h>

namespace vibrotherm::heat {

inline constexpr const char* kStepLadderAdapt = "ladder";

/// Registers the type with TSAdaptRegister (later calls replace it: harmless).
PetscErrorCode RegisterStepLadder();
/// Sets the first rung (and restarts its count); does nothing on an adaptor of another type.
PetscErrorCode StepLadderStart(TSAdapt adapt, PetscReal rung);

}  // namespace vibrotherm::heat

// -heat_free_ts_adapt_type ladder: a TSAdapt of vibrotherm's own for free
// diffusion (the heat TS once the waves are gone). The step stays on a rung for
// -heat_free_ts_adapt_ladder_steps steps, then grows by
// -heat_free_ts_adapt_ladder_ratio, starting from the step the TS was given.
//
// Why not error control: after the sources stop the rise varies on the time
// since they stopped, so steps growing geometrically with t follow it, and a
// step that repeats keeps the Jacobian (K + M/(θh)) and its Cholesky factor:
// one factorisation per rung instead of one per step (the paper scene's free
// phase: 157 factorisations, 12 ms each, with the basic adaptor). The schedule
// depends on nothing computed, so 1 and N ranks take the very same steps (an
// error-controlled step, rounded to a ladder, flips between rungs on rounding).
// Steps are clipped to hit output times (TS matchstep) and to
// -heat_free_ts_adapt_dt_min/max; the rung itself is kept.
#pragma once

#include <petscts.h>

namespace vibrotherm::heat {

inline constexpr const char* kStepLadderAdapt = "ladder";

/// Registers the type with TSAdaptRegister (later calls replace it: harmless).
PetscErrorCode RegisterStepLadder();

}  // namespace vibrotherm::heat

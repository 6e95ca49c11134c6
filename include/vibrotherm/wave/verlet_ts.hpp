// -wave_ts_type velocityverlet: velocity Verlet (drift–kick–drift) as a PETSc
// TS type of its own, the wave solver's default. The same scheme as
// basicsymplectic type 2 (bit for bit: same operations in the same order) on
// the same "position"/"momentum" RHS splits, but it makes its views of u and v
// once instead of four VecGetSubVector per step (each a new vector whose
// layout is set up by collectives: half the reductions of a wave step).
// Requires contiguous split index sets (the wave state [u; v] per rank).
#pragma once

#include <petscts.h>

namespace vibrotherm::wave {

inline constexpr const char* kVelocityVerletTS = "velocityverlet";

/// Registers the type with TSRegister (once; later calls do nothing).
PetscErrorCode RegisterVelocityVerletTS();

/// A multi-rate step of the caller's (local time stepping): each step calls
/// macro(ctx, t, h, position, momentum) instead of drift–kick–drift. Null: the plain step.
using VelocityVerletMacroStep = PetscErrorCode (*)(void* ctx, PetscReal t, PetscReal h, Vec q, Vec p);
PetscErrorCode VelocityVerletSetMacroStep(TS ts, VelocityVerletMacroStep macro, void* ctx);
/// Declares the position split's RHS to be the momentum itself (u̇ = v): the
/// drifts then add h/2 v directly instead of calling the RHS function, which
/// would copy v (same operations on the same values: the same bits). Does
/// nothing on a TS of another type.
PetscErrorCode VelocityVerletSetPositionRateIsMomentum(TS ts, PetscBool identity);

}  // namespace vibrotherm::wave

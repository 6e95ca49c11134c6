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

}  // namespace vibrotherm::wave

// The dimension of a scene and what a 3D scene may do yet. A 3D box
// (-specimen_depth > 0) runs the waves and the crack contact only: no heat solve,
// camera, modes, field output, crack probes or crack_state.csv, local time
// stepping, thermoelastic coupling, harmonic start, implicit waves, restart,
// mesh files, transducer patch or refinement. Each is refused naming its option.
#pragma once

#include "vibrotherm/coupling/run/scene.hpp"

namespace vibrotherm::coupling {

/// 3 when -specimen_depth > 0 (the specimen module declares and checks the option), else 2.
PetscErrorCode ReadSceneDimension(int* dimension);

/// In 3D: refuses what 3D does not support (one line naming the option, exit 2),
/// turns the automatic heat solve, periodic continuation and crack_state.csv off,
/// and says once that the run is waves-only. Nothing in 2D. Collective.
PetscErrorCode RestrictToDimension(MPI_Comm comm, Scene* scene);

}  // namespace vibrotherm::coupling

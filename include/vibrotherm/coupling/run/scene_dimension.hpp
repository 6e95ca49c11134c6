// The dimension of a scene and what a 3D scene may do yet. A 3D box
// (-specimen_depth > 0) or a 3D -mesh_file of hexahedra runs waves, contact, friction heat, camera, outputs,
// checkpoints, a transducer patch and the periodic continuation; not yet -physics
// heat, modes, crack probes, local time stepping, thermoelastic coupling, damping
// heat, harmonic start, implicit waves, mesh files or refinement: each is refused
// naming its option. The 3D-only face options are refused on a 2D specimen.
#pragma once

#include "vibrotherm/coupling/run/scene.hpp"

namespace vibrotherm::coupling {

/// 3 when -specimen_depth > 0 (the specimen module declares and checks the option) or
/// -mesh_file is a 3D mesh, else 2 (an unreadable -mesh_file is refused, naming it); the
/// file's own dimension in *file_dimension (0: no file), read once here: ReadScene hands it to
/// the specimen (MeshSource::file_dimension), which does not open the file for it again. Collective.
PetscErrorCode ReadSceneDimension(MPI_Comm comm, int* dimension, int* file_dimension);

/// In 3D: refuses what 3D does not support (one line naming the option, exit 2); in
/// 2D the 3D-only -heat_bc_front|back and -camera_face. Collective.
PetscErrorCode RestrictToDimension(MPI_Comm comm, Scene* scene);

}  // namespace vibrotherm::coupling

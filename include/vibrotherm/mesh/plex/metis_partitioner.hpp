// A "metis" PetscPartitioner for Debian's PETSc, which ships PT-Scotch but no
// METIS: after registration, -petscpartitioner_type metis selects it.
#pragma once

#include <petscsys.h>

namespace vibrotherm::mesh {

/// Registers the partitioner (idempotent). It partitions serial graphs (all
/// cells on one rank, which is how vibrotherm distributes its meshes) with
/// METIS_PartGraphKway; -petscpartitioner_metis_seed sets METIS' seed.
PetscErrorCode RegisterMetisPartitioner();

}  // namespace vibrotherm::mesh

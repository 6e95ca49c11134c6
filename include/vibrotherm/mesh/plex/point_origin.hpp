// Where each local point of a distributed mesh came from: its number in the
// serial mesh rank 0 built, which is the same whatever the rank count. The key
// under which checkpoints store dofs and contact cells (io/checkpoint.hpp), so
// that a run restarts on another partition too.
#pragma once

#include <petscdm.h>
#include <petscsf.h>

#include <vector>

namespace vibrotherm::mesh {

using PointOrigin = std::vector<PetscInt>;  ///< local point → serial point

/// From DMPlexDistribute's migration SF (null: not distributed, the identity). Collective on nothing.
PetscErrorCode OriginFromMigration(DM dm, PetscSF migration, PointOrigin* origin);

/// Keys of the owned dofs of dm's global vectors, in their order: origin × 8 + dof within the point.
PetscErrorCode OwnedDofKeys(DM dm, const PointOrigin& origin, std::vector<long long>* keys);

}  // namespace vibrotherm::mesh

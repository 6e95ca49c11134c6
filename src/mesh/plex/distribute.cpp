#include "vibrotherm/mesh/plex/distribute.hpp"

namespace vibrotherm::mesh {

PetscErrorCode DistributeMesh(DM* dm, const char* name, PointOrigin* origin) {
  PetscFunctionBeginUser;
  PetscPartitioner part;
  PetscCall(DMPlexGetPartitioner(*dm, &part));
  PetscCall(PetscPartitionerSetFromOptions(part));
  DM distributed = nullptr;
  PetscSF migration = nullptr;
  PetscCall(DMPlexDistribute(*dm, 0, &migration, &distributed));
  if (distributed) {
    PetscCall(DMDestroy(dm));
    *dm = distributed;
  }
  PetscCall(OriginFromMigration(*dm, migration, origin));
  PetscCall(PetscSFDestroy(&migration));
  PetscCall(PetscObjectSetName((PetscObject)*dm, name));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

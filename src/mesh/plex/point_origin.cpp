#include "vibrotherm/mesh/plex/point_origin.hpp"

#include <petscdmplex.h>
#include <petscsection.h>

namespace vibrotherm::mesh {

PetscErrorCode OriginFromMigration(DM dm, PetscSF migration, PointOrigin* origin) {
  PetscFunctionBeginUser;
  PetscInt start, end;
  PetscCall(DMPlexGetChart(dm, &start, &end));
  origin->resize(static_cast<std::size_t>(end - start));
  if (!migration) {
    for (PetscInt p = start; p < end; ++p) (*origin)[p - start] = p;
    PetscFunctionReturn(0);
  }
  PetscInt roots, leaves;
  const PetscInt* local;
  const PetscSFNode* remote;
  PetscCall(PetscSFGetGraph(migration, &roots, &leaves, &local, &remote));
  PetscCheck(leaves == end - start, PETSC_COMM_SELF, PETSC_ERR_PLIB, "migration SF has %" PetscInt_FMT " leaves for %" PetscInt_FMT " points",
             leaves, end - start);
  for (PetscInt i = 0; i < leaves; ++i) (*origin)[(local ? local[i] : i) - start] = remote[i].index;
  PetscFunctionReturn(0);
}

PetscErrorCode OwnedDofKeys(DM dm, const PointOrigin& origin, std::vector<long long>* keys) {
  PetscFunctionBeginUser;
  PetscSection global;
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscInt start, end, owned_start;
  PetscCall(PetscSectionGetChart(global, &start, &end));
  Vec probe;
  PetscCall(DMGetGlobalVector(dm, &probe));
  PetscInt n;
  PetscCall(VecGetOwnershipRange(probe, &owned_start, nullptr));
  PetscCall(VecGetLocalSize(probe, &n));
  PetscCall(DMRestoreGlobalVector(dm, &probe));
  keys->assign(static_cast<std::size_t>(n), -1);
  for (PetscInt p = start; p < end; ++p) {
    PetscInt dof, offset;
    PetscCall(PetscSectionGetDof(global, p, &dof));
    PetscCall(PetscSectionGetOffset(global, p, &offset));
    if (dof <= 0 || offset < 0) continue;  // not owned here
    PetscCheck(dof <= 8, PETSC_COMM_SELF, PETSC_ERR_SUP, "checkpoint keys: %" PetscInt_FMT " dofs on a point", dof);
    for (PetscInt d = 0; d < dof; ++d) (*keys)[offset - owned_start + d] = 8LL * origin[p] + d;
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

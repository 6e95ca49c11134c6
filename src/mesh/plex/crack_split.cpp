// The PyLith recipe: crack faces and their vertices in a "fault" label; the crack
// submesh, oriented, gives through its subpoint map the side of every point;
// DMPlexLabelCohesiveComplete completes it, DMPlexConstructCohesiveCells splits.
#include "vibrotherm/mesh/plex/crack_split.hpp"

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {

PetscErrorCode SplitCracks(DM dm, DM* split) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  DMLabel crack, tips;
  PetscCall(DMGetLabel(dm, labels::crack, &crack));
  PetscCall(DMGetLabel(dm, labels::crack_tip, &tips));
  PetscInt fStart, fEnd, nfaces = 0, total = 0;
  PetscCall(FacetRange(dm, &fStart, &fEnd));

  DMLabel fault;
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "vibrotherm_fault", &fault));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt v;
    PetscCall(DMLabelGetValue(crack, f, &v));
    if (v > 0) {
      PetscCall(DMLabelSetValue(fault, f, 1));
      ++nfaces;
    }
  }
  PetscCallMPI(MPI_Allreduce(&nfaces, &total, 1, MPIU_INT, MPI_SUM, comm));
  if (total == 0) {
    PetscCall(DMLabelDestroy(&fault));
    // Nothing to split: the same topology, but its own DM, so the wave and heat
    // spaces do not overwrite each other's section.
    PetscCall(DMClone(dm, split));
    PetscFunctionReturn(0);
  }
  PetscCall(DMPlexLabelComplete(dm, fault));

  // PETSc 3.18 reads the tip stratum without checking for an empty one: a crack
  // reaching the outer boundary at both ends has no tip, so give the label a
  // vertex off every crack, which DMPlexLabelCohesiveComplete discards.
  DMLabel tips_or_dummy;
  PetscCall(DMLabelDuplicate(tips, &tips_or_dummy));
  PetscInt ntips;
  PetscCall(DMLabelGetStratumSize(tips_or_dummy, 1, &ntips));
  if (ntips == 0) {
    PetscInt vStart, vEnd;
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    for (PetscInt v = vStart; v < vEnd; ++v) {
      PetscInt value;
      PetscCall(DMLabelGetValue(fault, v, &value));
      if (value < 0) {
        PetscCall(DMLabelSetValue(tips_or_dummy, v, 1));
        break;
      }
    }
  }

  DM crack_mesh;
  PetscCall(DMPlexCreateSubmesh(dm, fault, 1, PETSC_TRUE, &crack_mesh));
  PetscCall(DMPlexOrient(crack_mesh));
  DMLabel subpoints, cohesive;
  PetscCall(DMPlexGetSubpointMap(crack_mesh, &subpoints));
  PetscCall(DMLabelDuplicate(subpoints, &cohesive));
  PetscInt dim;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMLabelClearStratum(cohesive, dim));
  PetscCall(DMPlexLabelCohesiveComplete(dm, cohesive, tips_or_dummy, 1, PETSC_FALSE, crack_mesh));
  PetscCall(DMPlexConstructCohesiveCells(dm, cohesive, nullptr, split));
  PetscCall(PetscObjectSetName((PetscObject)*split, "specimen"));

  PetscCall(DMLabelDestroy(&cohesive));
  PetscCall(DMLabelDestroy(&tips_or_dummy));
  PetscCall(DMLabelDestroy(&fault));
  PetscCall(DMDestroy(&crack_mesh));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

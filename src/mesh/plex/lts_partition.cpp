#include "vibrotherm/mesh/plex/lts_partition.hpp"

#include <petsc/private/partitionerimpl.h>  // usevwgt: PETSc 3.18 has no setter

#include "vibrotherm/mesh/plex/plex_access.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vibrotherm::mesh {
namespace {

/// The shortest edge of a cell: the lengths of the depth-1 points of its closure (its
/// cone in 2D, the edges of its faces in 3D).
PetscErrorCode ShortestEdge(DM dm, PetscInt cell, double* h) {
  PetscFunctionBeginUser;
  PetscInt eStart, eEnd, size;
  PetscInt* closure = nullptr;
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &size, &closure));
  *h = INFINITY;
  for (PetscInt k = 0; k < 2 * size; k += 2) {
    if (closure[k] < eStart || closure[k] >= eEnd) continue;
    PetscReal length;
    PetscCall(DMPlexComputeCellGeometryFVM(dm, closure[k], &length, nullptr, nullptr));
    *h = std::min(*h, static_cast<double>(length));
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &size, &closure));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode SetLtsPartitionWeights(DM dm, const LtsWeighting& lts) {
  PetscFunctionBeginUser;
  if (!lts.on) PetscFunctionReturn(0);
  PetscInt cStart, cEnd, pStart, pEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  // Doublings of each bulk cell's shortest edge over the mesh's shortest (cohesive cells: none).
  std::vector<double> h(cEnd - cStart, -1.0);
  double h_min = INFINITY;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(IsCohesiveCell(dm, c, &cohesive));
    if (cohesive) continue;
    PetscCall(ShortestEdge(dm, c, &h[c - cStart]));
    h_min = std::min(h_min, h[c - cStart]);
  }
  std::vector<PetscInt> up(h.size(), 0);
  PetscInt top = 0;
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (h[k] <= 0.0) continue;
    up[k] = LtsDoublings(h[k] / h_min, lts.wiggle, lts.max_levels);
    top = std::max(top, up[k]);
  }
  PetscSection weights;
  PetscCall(PetscSectionCreate(PETSC_COMM_SELF, &weights));
  PetscCall(PetscSectionSetChart(weights, pStart, pEnd));
  for (PetscInt c = cStart; c < cEnd; ++c)
    PetscCall(PetscSectionSetDof(weights, c, h[c - cStart] > 0.0 ? PetscInt(1) << (top - up[c - cStart]) : 1));
  PetscCall(PetscSectionSetUp(weights));
  PetscCall(DMSetLocalSection(dm, weights));
  PetscCall(PetscSectionDestroy(&weights));
  PetscPartitioner part;
  PetscCall(DMPlexGetPartitioner(dm, &part));
  part->usevwgt = PETSC_TRUE;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

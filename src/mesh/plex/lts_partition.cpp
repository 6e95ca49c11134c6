#include "vibrotherm/mesh/plex/lts_partition.hpp"

#include <petsc/private/partitionerimpl.h>  // usevwgt: PETSc 3.18 has no setter

#include <algorithm>
#include <cmath>
#include <vector>

namespace vibrotherm::mesh {
namespace {

/// The shortest edge of a cell (the lengths of its cone's faces).
PetscErrorCode ShortestEdge(DM dm, PetscInt cell, double* h) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  PetscInt size;
  PetscCall(DMPlexGetConeSize(dm, cell, &size));
  PetscCall(DMPlexGetCone(dm, cell, &cone));
  *h = INFINITY;
  for (PetscInt k = 0; k < size; ++k) {
    PetscReal length;
    PetscCall(DMPlexComputeCellGeometryFVM(dm, cone[k], &length, nullptr, nullptr));
    *h = std::min(*h, static_cast<double>(length));
  }
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
    DMPolytopeType type;
    PetscCall(DMPlexGetCellType(dm, c, &type));
    if (type == DM_POLYTOPE_SEG_PRISM_TENSOR) continue;
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

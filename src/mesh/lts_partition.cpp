#include "vibrotherm/mesh/lts_partition.hpp"

#include <petsc/private/partitionerimpl.h>  // usevwgt: PETSc 3.18 has no setter

#include <algorithm>
#include <cmath>
#include <cstring>
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

PetscErrorCode SetLtsPartitionWeights(DM dm) {
  PetscFunctionBeginUser;
  char mode[16] = "off";
  PetscInt max_levels = 4;
  PetscReal wiggle = 1.0;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-wave_lts", mode, sizeof(mode), nullptr));
  if (std::strcmp(mode, "on") != 0) PetscFunctionReturn(0);
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-wave_lts_max_levels", &max_levels, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-wave_lts_wiggle", &wiggle, nullptr));
  if (max_levels < 1 || !(wiggle > 0.5 && wiggle <= 1.0)) PetscFunctionReturn(0);  // refused later, by the wave options
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
    up[k] = std::min<PetscInt>(max_levels - 1, static_cast<PetscInt>(std::floor(std::log2(h[k] / h_min / wiggle))));
    up[k] = std::max<PetscInt>(0, up[k]);
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

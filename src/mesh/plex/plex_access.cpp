#include "vibrotherm/mesh/plex/plex_access.hpp"

#include <petscsf.h>

namespace vibrotherm::mesh {

PetscErrorCode VertexCoordinates::Setup(DM dm) {
  PetscFunctionBeginUser;
  // Copied once per vertex, so that a lookup is an array access with nothing to fail.
  Vec local;
  PetscSection section;
  const PetscScalar* array;
  PetscInt dim;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  // Two coordinates a vertex: reading them from a 3D mesh would silently drop z.
  PetscCheck(dim == 2, PetscObjectComm((PetscObject)dm), PETSC_ERR_SUP,
             "VertexCoordinates: 2D meshes only (%" PetscInt_FMT "D)", dim);
  PetscCall(DMGetCoordinatesLocalSetUp(dm));
  PetscCall(DMGetCoordinatesLocal(dm, &local));
  PetscCall(DMGetCoordinateSection(dm, &section));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart_, nullptr));
  PetscInt vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, nullptr, &vEnd));
  coords_.resize(vEnd - vStart_);
  PetscCall(VecGetArrayRead(local, &array));
  for (PetscInt v = vStart_; v < vEnd; ++v) {
    PetscInt offset;
    PetscCall(PetscSectionGetOffset(section, v, &offset));
    coords_[v - vStart_] = {PetscRealPart(array[offset]), PetscRealPart(array[offset + 1])};
  }
  PetscCall(VecRestoreArrayRead(local, &array));
  PetscFunctionReturn(0);
}

PetscErrorCode CellCentroid(DM dm, const VertexCoordinates& x, PetscInt cell, std::array<double, 2>* centroid) {
  PetscFunctionBeginUser;
  PetscInt* closure = nullptr;
  PetscInt n, vStart, vEnd, count = 0;
  std::array<double, 2> c = {0, 0};
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure));
  for (PetscInt i = 0; i < 2 * n; i += 2)
    if (closure[i] >= vStart && closure[i] < vEnd) {
      const auto p = x(closure[i]);
      c[0] += p[0], c[1] += p[1], ++count;
    }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure));
  *centroid = {c[0] / count, c[1] / count};
  PetscFunctionReturn(0);
}

PetscErrorCode FacetRange(DM dm, PetscInt* fStart, PetscInt* fEnd) {
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 1, fStart, fEnd));
  PetscFunctionReturn(0);
}

PetscErrorCode IsFacet(DM dm, PetscInt p, bool* facet) {
  PetscFunctionBeginUser;
  PetscInt height;
  PetscCall(DMPlexGetPointHeight(dm, p, &height));
  *facet = height == 1;
  PetscFunctionReturn(0);
}

PetscErrorCode GhostPoints(DM dm, std::vector<bool>* ghost) {
  PetscFunctionBeginUser;
  PetscInt pStart, pEnd, nleaves;
  const PetscInt* leaves;
  PetscSF sf;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  ghost->assign(pEnd - pStart, false);
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  if (nleaves < 0) PetscFunctionReturn(0);  // graph not set: serial
  for (PetscInt i = 0; i < nleaves; ++i) (*ghost)[(leaves ? leaves[i] : i) - pStart] = true;
  PetscFunctionReturn(0);
}

PetscErrorCode IsCohesiveCell(DM dm, PetscInt c, bool* cohesive) {
  PetscFunctionBeginUser;
  DMPolytopeType type;
  PetscCall(DMPlexGetCellType(dm, c, &type));
  // Tensor prisms of a facet (2D: segment; 3D: triangle or quadrilateral), or of a point.
  *cohesive = type == DM_POLYTOPE_SEG_PRISM_TENSOR || type == DM_POLYTOPE_POINT_PRISM_TENSOR ||
              type == DM_POLYTOPE_TRI_PRISM_TENSOR || type == DM_POLYTOPE_QUAD_PRISM_TENSOR;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

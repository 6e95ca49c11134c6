#include "vibrotherm/mesh/plex/plex_access.hpp"

#include <petscsf.h>

namespace vibrotherm::mesh {

template <std::size_t D>
PetscErrorCode VertexPositions<D>::Setup(DM dm) {
  PetscFunctionBeginUser;
  // Copied once per vertex, so that a lookup is an array access with nothing to fail.
  Vec local;
  PetscSection section;
  const PetscScalar* array;
  PetscInt dim;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  PetscCheck(dim <= static_cast<PetscInt>(D), PetscObjectComm((PetscObject)dm), PETSC_ERR_SUP,
             "VertexPositions<%d> on a mesh with %" PetscInt_FMT " coordinates", static_cast<int>(D), dim);
  PetscCall(DMGetCoordinatesLocalSetUp(dm));
  PetscCall(DMGetCoordinatesLocal(dm, &local));
  PetscCall(DMGetCoordinateSection(dm, &section));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart_, nullptr));
  PetscInt vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, nullptr, &vEnd));
  coords_.assign(vEnd - vStart_, geometry::Point<D>{});  // a 2D mesh's points in 3D: z = 0
  PetscCall(VecGetArrayRead(local, &array));
  for (PetscInt v = vStart_; v < vEnd; ++v) {
    PetscInt offset;
    PetscCall(PetscSectionGetOffset(section, v, &offset));
    for (PetscInt d = 0; d < dim; ++d) coords_[v - vStart_][d] = PetscRealPart(array[offset + d]);
  }
  PetscCall(VecRestoreArrayRead(local, &array));
  PetscFunctionReturn(0);
}

template <std::size_t D>
PetscErrorCode CellCentroid(DM dm, const VertexPositions<D>& x, PetscInt cell, geometry::Point<D>* centroid) {
  PetscFunctionBeginUser;
  PetscInt* closure = nullptr;
  PetscInt n, vStart, vEnd, count = 0;
  geometry::Point<D> c{};
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure));
  for (PetscInt i = 0; i < 2 * n; i += 2)
    if (closure[i] >= vStart && closure[i] < vEnd) {
      const auto p = x(closure[i]);
      for (std::size_t d = 0; d < D; ++d) c[d] += p[d];
      ++count;
    }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure));
  for (std::size_t d = 0; d < D; ++d) (*centroid)[d] = c[d] / count;
  PetscFunctionReturn(0);
}

template class VertexPositions<2>;
template class VertexPositions<3>;
template PetscErrorCode CellCentroid<2>(DM, const VertexPositions<2>&, PetscInt, geometry::Point<2>*);
template PetscErrorCode CellCentroid<3>(DM, const VertexPositions<3>&, PetscInt, geometry::Point<3>*);

PetscErrorCode FaceCycle(DM dm, PetscInt face, std::vector<PetscInt>* corners, std::vector<PetscInt>* edges) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  PetscInt n;
  PetscCall(DMPlexGetConeSize(dm, face, &n));
  PetscCall(DMPlexGetCone(dm, face, &cone));
  std::vector<std::array<PetscInt, 2>> ends(n);
  for (PetscInt k = 0; k < n; ++k) {
    const PetscInt* v;
    PetscCall(DMPlexGetCone(dm, cone[k], &v));
    ends[k] = {v[0], v[1]};
  }
  std::vector<bool> used(n, false);
  corners->assign(1, ends[0][0]);
  edges->clear();
  for (PetscInt step = 0; step < n; ++step)
    for (PetscInt k = 0; k < n; ++k) {
      if (used[k] || (ends[k][0] != corners->back() && ends[k][1] != corners->back())) continue;
      used[k] = true;
      edges->push_back(cone[k]);
      if (step + 1 < n) corners->push_back(ends[k][0] == corners->back() ? ends[k][1] : ends[k][0]);
      break;
    }
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

PetscErrorCode CohesiveCells(DM dm, std::vector<PetscInt>* cells) {
  PetscFunctionBeginUser;
  cells->clear();
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(IsCohesiveCell(dm, c, &cohesive));
    if (cohesive) cells->push_back(c);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode StratumPoints(DM dm, const char* label, PetscInt value, std::vector<PetscInt>* points) {
  PetscFunctionBeginUser;
  points->clear();
  DMLabel l;
  IS is = nullptr;
  PetscCall(DMGetLabel(dm, label, &l));
  if (l) PetscCall(DMLabelGetStratumIS(l, value, &is));
  if (!is) PetscFunctionReturn(0);
  PetscInt n;
  const PetscInt* p;
  PetscCall(ISGetLocalSize(is, &n));
  PetscCall(ISGetIndices(is, &p));
  points->assign(p, p + n);
  PetscCall(ISRestoreIndices(is, &p));
  PetscCall(ISDestroy(&is));
  PetscFunctionReturn(0);
}

PetscErrorCode MoveVertices(DM dm, const std::function<void(PetscScalar* x, PetscInt n)>& move) {
  PetscFunctionBeginUser;
  Vec coordinates;
  PetscScalar* x;
  PetscInt n;
  PetscCall(DMGetCoordinatesLocal(dm, &coordinates));
  PetscCall(VecGetLocalSize(coordinates, &n));
  PetscCall(VecGetArray(coordinates, &x));
  move(x, n);
  PetscCall(VecRestoreArray(coordinates, &x));
  PetscCall(DMSetCoordinatesLocal(dm, coordinates));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

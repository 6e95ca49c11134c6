#include "vibrotherm/mesh/plex_access.hpp"

#include <petscsf.h>

namespace vibrotherm::mesh {

PetscErrorCode VertexCoordinates::Setup(DM dm) {
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocalSetUp(dm));
  PetscCall(DMGetCoordinatesLocal(dm, &local_));
  PetscCall(DMGetCoordinateSection(dm, &section_));
  PetscCall(VecGetArrayRead(local_, &array_));
  PetscFunctionReturn(0);
}

VertexCoordinates::~VertexCoordinates() {
  if (array_) (void)VecRestoreArrayRead(local_, &array_);
}

std::array<double, 2> VertexCoordinates::operator()(PetscInt vertex) const {
  PetscInt offset = 0;
  (void)PetscSectionGetOffset(section_, vertex, &offset);
  return {PetscRealPart(array_[offset]), PetscRealPart(array_[offset + 1])};
}

std::array<double, 2> CellCentroid(DM dm, const VertexCoordinates& x, PetscInt cell) {
  PetscInt* closure = nullptr;
  PetscInt n, vStart, vEnd, count = 0;
  std::array<double, 2> c = {0, 0};
  (void)DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd);
  (void)DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure);
  for (PetscInt i = 0; i < 2 * n; i += 2)
    if (closure[i] >= vStart && closure[i] < vEnd) {
      const auto p = x(closure[i]);
      c[0] += p[0], c[1] += p[1], ++count;
    }
  (void)DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure);
  return {c[0] / count, c[1] / count};
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
  *cohesive = type == DM_POLYTOPE_SEG_PRISM_TENSOR || type == DM_POLYTOPE_POINT_PRISM_TENSOR;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

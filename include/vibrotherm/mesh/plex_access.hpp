// Small read helpers over a DMPlex: vertex coordinates and point ownership.
#pragma once

#include <petscdmplex.h>

#include <array>
#include <vector>

namespace vibrotherm::mesh {

/// Coordinates of vertices from the local coordinate vector.
class VertexCoordinates {
 public:
  PetscErrorCode Setup(DM dm);
  ~VertexCoordinates();
  std::array<double, 2> operator()(PetscInt vertex) const;

 private:
  Vec local_ = nullptr;
  const PetscScalar* array_ = nullptr;
  PetscSection section_ = nullptr;
};

/// Centroid of a cell: the mean of its closure vertices.
std::array<double, 2> CellCentroid(DM dm, const VertexCoordinates& x, PetscInt cell);

/// Marks the points this rank does not own (leaves of the point SF).
PetscErrorCode GhostPoints(DM dm, std::vector<bool>* ghost);

/// Whether cell c is a cohesive (crack) cell.
PetscErrorCode IsCohesiveCell(DM dm, PetscInt c, bool* cohesive);

}  // namespace vibrotherm::mesh

// Small read helpers over a DMPlex: vertex coordinates and point ownership.
#pragma once

#include <petscdmplex.h>

#include <array>
#include <vector>

namespace vibrotherm::mesh {

/// Coordinates of the vertices of a DM (copied once by Setup).
class VertexCoordinates {
 public:
  PetscErrorCode Setup(DM dm);
  std::array<double, 2> operator()(PetscInt vertex) const { return coords_[vertex - vStart_]; }

 private:
  std::vector<std::array<double, 2>> coords_;
  PetscInt vStart_ = 0;
};

/// Centroid of a cell: the mean of its closure vertices.
PetscErrorCode CellCentroid(DM dm, const VertexCoordinates& x, PetscInt cell, std::array<double, 2>* centroid);

/// Marks the points this rank does not own (leaves of the point SF).
PetscErrorCode GhostPoints(DM dm, std::vector<bool>* ghost);

/// The facets of a DMPlex: the points of height 1 (edges in 2D, faces in 3D).
PetscErrorCode FacetRange(DM dm, PetscInt* fStart, PetscInt* fEnd);

/// Whether point p is a facet (height 1).
PetscErrorCode IsFacet(DM dm, PetscInt p, bool* facet);

/// Whether cell c is a cohesive (crack) cell.
PetscErrorCode IsCohesiveCell(DM dm, PetscInt c, bool* cohesive);

}  // namespace vibrotherm::mesh

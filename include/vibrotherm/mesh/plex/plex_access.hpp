// Small read helpers over a DMPlex: vertex coordinates and point ownership.
#pragma once

#include <petscdmplex.h>

#include <array>
#include <functional>
#include <vector>

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::mesh {

/// Coordinates of the vertices of a DM with D coordinates (copied once by
/// Setup, which refuses a mesh of another coordinate dimension: reading a 3D
/// mesh with two coordinates would silently drop z).
template <std::size_t D>
class VertexPositions {
 public:
  PetscErrorCode Setup(DM dm);
  geometry::Point<D> operator()(PetscInt vertex) const { return coords_[vertex - vStart_]; }

 private:
  std::vector<geometry::Point<D>> coords_;
  PetscInt vStart_ = 0;
};

/// The planar accessor the 2D code uses.
using VertexCoordinates = VertexPositions<2>;

/// Centroid of a cell: the mean of its closure vertices (D = 2 or 3).
template <std::size_t D>
PetscErrorCode CellCentroid(DM dm, const VertexPositions<D>& x, PetscInt cell, geometry::Point<D>* centroid);

/// The corners of a 2D polygon point (a face of a 3D mesh) in cyclic order,
/// found by walking its edges, and its edges in the same order: edges[k] joins
/// corners[k] and corners[k + 1] (mod the corner count).
PetscErrorCode FaceCycle(DM dm, PetscInt face, std::vector<PetscInt>* corners, std::vector<PetscInt>* edges);

/// Moves the vertices of a (serial or not yet distributed) mesh: move(x, n) edits its n local
/// coordinates in place (the coordinate dimension's values a vertex).
PetscErrorCode MoveVertices(DM dm, const std::function<void(PetscScalar* x, PetscInt n)>& move);

/// The points of a label's stratum on this rank (none when the label or the stratum is absent).
PetscErrorCode StratumPoints(DM dm, const char* label, PetscInt value, std::vector<PetscInt>* points);

/// Marks the points this rank does not own (leaves of the point SF).
PetscErrorCode GhostPoints(DM dm, std::vector<bool>* ghost);

/// The facets of a DMPlex: the points of height 1 (edges in 2D, faces in 3D).
PetscErrorCode FacetRange(DM dm, PetscInt* fStart, PetscInt* fEnd);

/// Whether point p is a facet (height 1).
PetscErrorCode IsFacet(DM dm, PetscInt p, bool* facet);

/// Whether cell c is a cohesive (crack) cell.
PetscErrorCode IsCohesiveCell(DM dm, PetscInt c, bool* cohesive);

/// This rank's cohesive cells, in point order.
PetscErrorCode CohesiveCells(DM dm, std::vector<PetscInt>* cells);

}  // namespace vibrotherm::mesh

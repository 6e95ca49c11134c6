// A cell's corner coordinates and the map from its reference cell, fast: the
// corners at the reference corners (simplex vertices, or the 2^dim tensor corners
// in Gray-code order, CornerSign) and the affine or multilinear map through them,
// PETSc's own for a P1/Q1 coordinate field. The cell locator and the node
// positions of a Lagrange space use them instead of DMPlexReferenceToCoordinates
// (~3 ms a call in PETSc 3.18: a minute for 20k hexahedra).
#pragma once

#include <petscdmplex.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::fe {

/// Sign (±1) of axis d at tensor corner k, corners in Gray-code order so that
/// consecutive corners share an edge (2D: counter-clockwise from (−1, −1)).
inline double CornerSign(int k, int d) { return ((k ^ (k >> 1)) >> d) & 1 ? 1.0 : -1.0; }

/// The reference corners: the simplex's vertices, or the 2^dim tensor corners (CornerSign).
std::vector<double> ReferenceCorners(int dim, bool simplex);

/// The point at reference coordinates r of the cell with these corners (dim each, in ReferenceCorners' order).
ReferencePoint MapToCell(const double* corners, int dim, bool simplex, const ReferencePoint& r);

/// Reads cells' corners at the reference corners. DMPlexReferenceToCoordinates is
/// called on the first cell to learn which closure vertex sits at each reference
/// corner (the same for every cell: the closure order is what the reference map is
/// built on) and again on every 256th to check that; the others read their
/// closure's coordinates.
class CellCorners {
 public:
  CellCorners(DM dm, int dim, bool simplex);
  int corners() const { return corners_; }
  /// x: corners() × dim coordinates of cell c.
  PetscErrorCode Read(PetscInt c, double* x);

 private:
  PetscErrorCode Closure(PetscInt c, PetscInt* n, PetscScalar** v, bool restore) const;
  PetscErrorCode Learn(PetscInt c, const double* x);

  DM dm_;
  int dim_, corners_;
  std::vector<double> ref_;
  std::vector<int> order_;
  long count_ = 0;
};

}  // namespace vibrotherm::fe

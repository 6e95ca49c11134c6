// Many points located in the local bulk cells of a space, fast: a uniform grid
// of bins over the cells' bounding boxes, then the cell's own map inverted by
// Newton (bilinear quads and trilinear hexahedra, affine triangles and
// tetrahedra) instead of DMPlexCoordinatesToReference (~3 ms a call in PETSc
// 3.18). The map is PETSc's: its corners come from DMPlexReferenceToCoordinates,
// so reference coordinates mean what PetscFE expects. The dimension is the
// space's (the DM's): 2 or 3.
#pragma once

#include <petscdmplex.h>

#include <array>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/util/point_exchange.hpp"

namespace vibrotherm::fe {

class CellLocator {
 public:
  PetscErrorCode Setup(const LagrangeSpace& space);
  /// The local bulk cell holding point (dim coordinates; first found) and the
  /// reference coordinates; cell = -1 when none.
  void Locate(const double* point, PetscInt* cell, ReferencePoint* ref) const;
  /// d x/d ξ of a located cell at a reference point (row-major dim × dim).
  std::array<double, 9> Jacobian(PetscInt cell, const ReferencePoint& ref) const;
  /// 2D forms of the two above.
  void Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const;
  std::array<double, 4> Jacobian(PetscInt cell, const std::array<double, 2>& ref) const;
  /// The bounding box of the local cells' corners (z from 0 to 0 in 2D; empty when no cells).
  const util::Box& bounds() const { return bounds_; }

 private:
  struct Cell {
    PetscInt point;
    /// Coordinates of the reference corners, dim each: simplices' vertices, or
    /// the tensor corners in Gray-code order (2D: counter-clockwise).
    std::array<double, 24> corners;
  };
  bool Inside(const Cell& c, const double* x, ReferencePoint* ref) const;
  ReferencePoint Map(const Cell& c, const ReferencePoint& ref) const;
  std::array<double, 9> MapJacobian(const Cell& c, const ReferencePoint& ref) const;
  /// The grid of bins over the box [lo, hi] and the cells listed in the bins they overlap.
  void FillBins(const double* lo, const double* hi);
  std::vector<Cell> cells_;
  std::vector<std::size_t> index_of_point_;  ///< cell point − first cell → index in cells_
  PetscInt first_point_ = 0;
  bool simplex_ = false;
  int dim_ = 2, corners_ = 4;
  std::array<double, 3> origin_ = {0, 0, 0};
  double bin_ = 1;
  std::array<int, 3> bins_per_axis_ = {0, 0, 1};
  std::vector<std::vector<std::size_t>> bins_;
  util::Box bounds_;
};

}  // namespace vibrotherm::fe

// Friction heat as a density on a crack's faces → heat load, in both dimensions
// (2D: points on the crack lines, z = 0, their lengths as "areas"; surface_points.hpp
// for the source).
//
// The source points carry areas A_p and, per exchange, densities q_p [W/m²].
// The heat load is the heat basis at each point times its power:
//   Q_h = Σ_p T_hp q_p,   T_hp = A_p ψ_h(x_p),
// a sparse matrix (heat dofs × source points) built once, one MatMultAdd per
// heat step. The heat basis sums to one at every point, so
// Σ_h Q_h = Σ_p A_p q_p: heat deposited = power given, to rounding, whatever
// the meshes. Where the points are the Gauss points of the wave crack faces
// (crack_face_quadrature.hpp), ψ_h q is integrated to the order of that rule on
// every piece of a face: exactly where the heat basis is one polynomial on it.
//
// Each rank gives its own points (columns in that layout); each point goes only
// to the ranks whose heat cells' bounding box holds it (fe/point_owners.hpp, a
// PetscSF), they locate it in their cells (fe::CellLocator) and the lowest rank
// holding a point adds its column, so a point on a partition boundary is counted
// once and 1 and N ranks build the same matrix. A point outside the heat mesh is an error.
#pragma once

#include <petscmat.h>

#include <vector>

#include "vibrotherm/coupling/exchange/surface_points.hpp"
#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::coupling {

class SurfaceHeatTransfer {
 public:
  SurfaceHeatTransfer() = default;
  SurfaceHeatTransfer(const SurfaceHeatTransfer&) = delete;
  SurfaceHeatTransfer& operator=(const SurfaceHeatTransfer&) = delete;
  ~SurfaceHeatTransfer();

  /// Builds T for this rank's points on heat_space's mesh (2D or 3D). Collective.
  PetscErrorCode Setup(const fe::LagrangeSpace& heat_space, const SurfacePoints& mine);
  /// Q += T q for the densities q_p [W/m²] of this rank's points. Collective.
  PetscErrorCode AddRates(const std::vector<double>& density, Vec Q);
  /// T itself (heat dofs × points), owned by this object.
  Mat matrix() const { return transfer_; }
  /// Σ A_p over every rank's points [m²].
  double area() const { return area_; }
  /// Global index of this rank's first point.
  PetscInt first_point() const { return first_point_; }

 private:
  /// Rows and values of point p's column in T: the closure dofs of its cell and A_p ψ there.
  PetscErrorCode AddColumn(const fe::LagrangeSpace& heat_space, Mat T, PetscInt column, PetscInt cell,
                           const fe::ReferencePoint& ref, double area);
  Mat transfer_ = nullptr;  ///< T: heat dofs × source points
  Vec rate_ = nullptr;      ///< q per source point (this rank's points)
  double area_ = 0.0;
  PetscInt first_point_ = 0;
};

}  // namespace vibrotherm::coupling

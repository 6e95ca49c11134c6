// A friction power density on a crack, as the heat side receives it (plain C++,
// no PETSc): points on the crack (a 3D crack plane, or a 2D crack line with z = 0),
// each with the area it stands for [m²] (in 2D the length [m]); per exchange a
// power per unit area q_p [W/m²] at
// every point. The power is Σ_p A_p q_p: the points are a quadrature of the
// crack's density (the contact cells with their tributary areas, or the Gauss
// points of the wave mesh's crack faces with their weights), and
// coupling/exchange/surface_transfer moves it onto the heat dofs without losing
// any of it.
//
// DiscSector builds such a set for a uniform source over a sector of a disc
// (the closed-form cases of 3D-NOTES.md §4.3): a polar grid of `radial` ×
// `angular` cells, a point at the centre of each, A = r Δr Δθ (the annular
// cell's exact area, so Σ A = (θ1 − θ0) R²/2 to rounding). Rectangle: a grid
// of n1 × n2 equal cells, 2 × 2 Gauss points in each (a uniform density over
// cells that are faces of the heat mesh is then transferred exactly, Q1 and Q2).
#pragma once

#include <vector>

#include "vibrotherm/geometry/frame.hpp"

namespace vibrotherm::coupling {

struct SurfacePoints {
  std::vector<geometry::Vec3> x;  ///< positions on the crack plane [m]
  std::vector<double> area;       ///< the area each stands for [m²]
  std::size_t size() const { return x.size(); }
  double total_area() const;
};

/// The sector θ0 ≤ θ ≤ θ1 of the disc of `radius` about `centre` in the plane of
/// `frame` (θ from tangent[0] towards tangent[1]).
SurfacePoints DiscSector(const geometry::Vec3& centre, const geometry::Frame<3>& frame, double radius, double theta0,
                         double theta1, int radial, int angular);

/// The rectangle [−h1, h1] × [−h2, h2] about `centre` along the frame's tangents.
SurfacePoints Rectangle(const geometry::Vec3& centre, const geometry::Frame<3>& frame, double h1, double h2, int n1,
                        int n2);

}  // namespace vibrotherm::coupling

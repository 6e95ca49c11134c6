// The lumped weights w = ∫φ dA of the Lagrange nodes on one face of a 3D mesh
// (a quadrilateral facet of a hexahedron, Q1/Q2, or a triangle facet of a
// tetrahedron, P1/P2): the trace of the cell's basis on the face is the face's
// own Lagrange basis, so the weights depend only on the face's corners.
// PETSc-free: the space maps the nodes to dofs.
#pragma once

#include <vector>

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::fe {

/// Per node of a face: the corners in the order given, the edge from corner k
/// to corner k + 1 (mod the corner count; degree 2 only), the interior node
/// (a Q2 quadrilateral only, else 0); and the face's area (Σ of all weights).
struct FaceNodeWeights {
  std::vector<double> corner, edge;
  double interior = 0.0, area = 0.0;
};

/// Weights of a face with 3 (triangle) or 4 (quadrilateral, corners in cyclic
/// order) corners, degree 1 or 2. Triangles are affine: closed forms. A
/// quadrilateral maps bilinearly: a 3×3 Gauss rule on its own map, exact when
/// it is planar.
FaceNodeWeights FaceWeights(const std::vector<geometry::Vec3>& corners, int degree);

}  // namespace vibrotherm::fe

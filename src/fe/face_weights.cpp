#include "vibrotherm/fe/face_weights.hpp"

#include <cmath>

namespace vibrotherm::fe {
namespace {

using geometry::Vec3;

/// The 1D Lagrange function of the node at p ∈ {−1, 0, 1} (0: degree 2 only) at ξ.
double Lagrange1D(int degree, int p, double xi) {
  if (degree == 1) return 0.5 * (1.0 + p * xi);
  if (p == 0) return 1.0 - xi * xi;
  return 0.5 * xi * (xi + p);
}

FaceNodeWeights TriangleWeights(const std::vector<Vec3>& c, int degree) {
  FaceNodeWeights w;
  w.area = 0.5 * geometry::Norm(geometry::Cross(geometry::Sub(c[1], c[0]), geometry::Sub(c[2], c[0])));
  // P1: A/3 at each corner; P2: the corner functions integrate to zero, the edge ones to A/3.
  w.corner.assign(3, degree == 1 ? w.area / 3.0 : 0.0);
  if (degree == 2) w.edge.assign(3, w.area / 3.0);
  return w;
}

FaceNodeWeights QuadWeights(const std::vector<Vec3>& c, int degree) {
  // Reference corners in cyclic order; the edge k midpoint lies between corners k and k + 1.
  constexpr int kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
  const double g = std::sqrt(0.6), points[3] = {-g, 0.0, g}, weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  FaceNodeWeights w;
  w.corner.assign(4, 0.0);
  if (degree == 2) w.edge.assign(4, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double xi = points[i], eta = points[j];
      Vec3 dxi{}, deta{};
      for (int k = 0; k < 4; ++k) {
        dxi = geometry::Add(dxi, geometry::Scale(0.25 * kXi[k] * (1.0 + kEta[k] * eta), c[k]));
        deta = geometry::Add(deta, geometry::Scale(0.25 * kEta[k] * (1.0 + kXi[k] * xi), c[k]));
      }
      const double dA = weights[i] * weights[j] * geometry::Norm(geometry::Cross(dxi, deta));
      const auto shape = [&](int p, int q) { return Lagrange1D(degree, p, xi) * Lagrange1D(degree, q, eta); };
      w.area += dA;
      for (int k = 0; k < 4; ++k) {
        w.corner[k] += dA * shape(kXi[k], kEta[k]);
        const int next = (k + 1) % 4;
        if (degree == 2) w.edge[k] += dA * shape((kXi[k] + kXi[next]) / 2, (kEta[k] + kEta[next]) / 2);
      }
      if (degree == 2) w.interior += dA * shape(0, 0);
    }
  return w;
}

}  // namespace

FaceNodeWeights FaceWeights(const std::vector<Vec3>& corners, int degree) {
  return corners.size() == 3 ? TriangleWeights(corners, degree) : QuadWeights(corners, degree);
}

}  // namespace vibrotherm::fe

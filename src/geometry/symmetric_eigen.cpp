#include "vibrotherm/geometry/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::geometry {

SymmetricEigen3 EigenSymmetric3(const std::array<Vec3, 3>& a_in) {
  std::array<Vec3, 3> a = a_in, v = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j) a[i][j] = a[j][i];
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = std::abs(a[0][1]) + std::abs(a[0][2]) + std::abs(a[1][2]);
    const double scale = std::abs(a[0][0]) + std::abs(a[1][1]) + std::abs(a[2][2]);
    if (off <= 1e-15 * scale || off == 0.0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        // The rotation in the (p, q) plane that zeroes a[p][q].
        const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a ← a G (columns p, q)
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a ← Gᵀ a (rows p, q)
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // the eigenvectors are the columns of v G
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] > a[j][j]; });
  SymmetricEigen3 e;
  for (int k = 0; k < 3; ++k) {
    e.value[k] = a[order[k]][order[k]];
    e.vector[k] = {v[0][order[k]], v[1][order[k]], v[2][order[k]]};
  }
  return e;
}

}  // namespace vibrotherm::geometry

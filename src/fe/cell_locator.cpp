#include "vibrotherm/fe/cell_locator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibrotherm::fe {

PetscErrorCode CellLocator::Setup(const LagrangeSpace& space) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  // Bilinear quads and affine triangles, 2D bins: a 3D mesh needs trilinear/tet maps (issue 25).
  PetscCheck(space.dim() == 2, PetscObjectComm((PetscObject)dm), PETSC_ERR_SUP, "CellLocator: 2D meshes only (%dD)",
             space.dim());
  simplex_ = space.simplex();
  const std::vector<double> ref_corners = simplex_ ? std::vector<double>{-1, -1, 1, -1, -1, 1}
                                                   : std::vector<double>{-1, -1, 1, -1, 1, 1, -1, 1};
  const PetscInt ncorners = static_cast<PetscInt>(ref_corners.size() / 2);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  cells_.clear();
  for (PetscInt c : space.cells()) {
    Cell cell{c, {}};
    PetscCall(DMPlexReferenceToCoordinates(dm, c, ncorners, ref_corners.data(), cell.corners.data()));
    for (PetscInt k = 0; k < ncorners; ++k)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], cell.corners[2 * k + d]), hi[d] = std::max(hi[d], cell.corners[2 * k + d]);
    cells_.push_back(cell);
  }
  if (cells_.empty()) PetscFunctionReturn(0);
  first_point_ = cells_.front().point;
  index_of_point_.assign(cells_.back().point - first_point_ + 1, std::numeric_limits<std::size_t>::max());
  for (std::size_t i = 0; i < cells_.size(); ++i) index_of_point_[cells_[i].point - first_point_] = i;
  // About one cell a bin.
  const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
  bin_ = std::max(1e-300, std::sqrt(area / static_cast<double>(cells_.size())));
  x0_ = lo[0], y0_ = lo[1];
  nx_ = std::max(1, static_cast<int>(std::ceil((hi[0] - lo[0]) / bin_)));
  ny_ = std::max(1, static_cast<int>(std::ceil((hi[1] - lo[1]) / bin_)));
  bins_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    double clo[2] = {INFINITY, INFINITY}, chi[2] = {-INFINITY, -INFINITY};
    for (PetscInt k = 0; k < ncorners; ++k)
      for (int d = 0; d < 2; ++d)
        clo[d] = std::min(clo[d], cells_[i].corners[2 * k + d]), chi[d] = std::max(chi[d], cells_[i].corners[2 * k + d]);
    const int i0 = std::clamp(static_cast<int>((clo[0] - x0_) / bin_), 0, nx_ - 1);
    const int i1 = std::clamp(static_cast<int>((chi[0] - x0_) / bin_), 0, nx_ - 1);
    const int j0 = std::clamp(static_cast<int>((clo[1] - y0_) / bin_), 0, ny_ - 1);
    const int j1 = std::clamp(static_cast<int>((chi[1] - y0_) / bin_), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int k = i0; k <= i1; ++k) bins_[static_cast<std::size_t>(j) * nx_ + k].push_back(i);
  }
  PetscFunctionReturn(0);
}

std::array<double, 2> CellLocator::Map(const Cell& c, const std::array<double, 2>& r) const {
  const auto& p = c.corners;
  if (simplex_) {  // affine: x = p0 + (p1 − p0)(ξ + 1)/2 + (p2 − p0)(η + 1)/2
    const double s = 0.5 * (r[0] + 1), t = 0.5 * (r[1] + 1);
    return {p[0] + s * (p[2] - p[0]) + t * (p[4] - p[0]), p[1] + s * (p[3] - p[1]) + t * (p[5] - p[1])};
  }
  const double n[4] = {0.25 * (1 - r[0]) * (1 - r[1]), 0.25 * (1 + r[0]) * (1 - r[1]), 0.25 * (1 + r[0]) * (1 + r[1]),
                       0.25 * (1 - r[0]) * (1 + r[1])};
  return {n[0] * p[0] + n[1] * p[2] + n[2] * p[4] + n[3] * p[6], n[0] * p[1] + n[1] * p[3] + n[2] * p[5] + n[3] * p[7]};
}

std::array<double, 4> CellLocator::MapJacobian(const Cell& c, const std::array<double, 2>& r) const {
  const auto& p = c.corners;
  if (simplex_) return {0.5 * (p[2] - p[0]), 0.5 * (p[4] - p[0]), 0.5 * (p[3] - p[1]), 0.5 * (p[5] - p[1])};
  const double dxi[4] = {-0.25 * (1 - r[1]), 0.25 * (1 - r[1]), 0.25 * (1 + r[1]), -0.25 * (1 + r[1])};
  const double deta[4] = {-0.25 * (1 - r[0]), -0.25 * (1 + r[0]), 0.25 * (1 + r[0]), 0.25 * (1 - r[0])};
  std::array<double, 4> J{};
  for (int k = 0; k < 4; ++k) {
    J[0] += dxi[k] * p[2 * k], J[1] += deta[k] * p[2 * k];
    J[2] += dxi[k] * p[2 * k + 1], J[3] += deta[k] * p[2 * k + 1];
  }
  return J;
}

bool CellLocator::Inside(const Cell& c, double x, double y, std::array<double, 2>* ref) const {
  std::array<double, 2> r = {0.0, 0.0};
  if (simplex_) r = {-1.0 / 3.0, -1.0 / 3.0};
  bool converged = false;
  for (int it = 0; it < 20 && !converged; ++it) {  // Newton on x(r) = (x, y); one step for triangles
    const auto X = Map(c, r);
    const auto J = MapJacobian(c, r);
    const double fx = X[0] - x, fy = X[1] - y, det = J[0] * J[3] - J[1] * J[2];
    const double d0 = (J[3] * fx - J[1] * fy) / det, d1 = (-J[2] * fx + J[0] * fy) / det;
    r[0] -= d0, r[1] -= d1;
    converged = std::abs(d0) + std::abs(d1) < 1e-12;
  }
  *ref = r;
  // From a point well outside a bilinear quad Newton may wander and stop inside
  // [-1, 1]² without having converged: such a cell does not hold the point.
  if (!converged && !simplex_) return false;
  const double tol = 1e-10;
  return simplex_ ? (r[0] >= -1 - tol && r[1] >= -1 - tol && r[0] + r[1] <= tol)
                  : (std::abs(r[0]) <= 1 + tol && std::abs(r[1]) <= 1 + tol);
}

void CellLocator::Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const {
  *cell = -1;
  if (bins_.empty()) return;
  const int i = static_cast<int>(std::floor((x - x0_) / bin_)), j = static_cast<int>(std::floor((y - y0_) / bin_));
  if (i < 0 || j < 0 || i >= nx_ || j >= ny_) {
    // a point on the far edge of the box belongs to the last bin
    if (i > nx_ || j > ny_ || i < -1 || j < -1) return;
  }
  const std::size_t b = static_cast<std::size_t>(std::clamp(j, 0, ny_ - 1)) * nx_ + std::clamp(i, 0, nx_ - 1);
  for (std::size_t k : bins_[b])
    if (Inside(cells_[k], x, y, ref)) {
      *cell = cells_[k].point;
      return;
    }
}

std::array<double, 4> CellLocator::Jacobian(PetscInt cell, const std::array<double, 2>& ref) const {
  return MapJacobian(cells_[index_of_point_[cell - first_point_]], ref);
}

}  // namespace vibrotherm::fe

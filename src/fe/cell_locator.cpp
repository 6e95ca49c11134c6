#include "vibrotherm/fe/cell_locator.hpp"

#include "vibrotherm/fe/cell_corners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibrotherm::fe {
namespace {

/// One Newton correction: J d = f for a dim × dim row-major J, by its adjugate.
void SolveJacobian(const std::array<double, 9>& J, const double* f, int dim, double* d) {
  if (dim == 2) {
    const double det = J[0] * J[3] - J[1] * J[2];
    d[0] = (J[3] * f[0] - J[1] * f[1]) / det, d[1] = (-J[2] * f[0] + J[0] * f[1]) / det;
    return;
  }
  const double adj[9] = {J[4] * J[8] - J[5] * J[7], J[2] * J[7] - J[1] * J[8], J[1] * J[5] - J[2] * J[4],
                         J[5] * J[6] - J[3] * J[8], J[0] * J[8] - J[2] * J[6], J[2] * J[3] - J[0] * J[5],
                         J[3] * J[7] - J[4] * J[6], J[1] * J[6] - J[0] * J[7], J[0] * J[4] - J[1] * J[3]};
  const double det = J[0] * adj[0] + J[1] * adj[3] + J[2] * adj[6];
  for (int i = 0; i < 3; ++i) d[i] = (adj[3 * i] * f[0] + adj[3 * i + 1] * f[1] + adj[3 * i + 2] * f[2]) / det;
}

}  // namespace

PetscErrorCode CellLocator::Setup(const LagrangeSpace& space) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  simplex_ = space.simplex();
  dim_ = space.dim();
  const int D = dim_;
  CellCorners reader(dm, D, simplex_);
  corners_ = reader.corners();
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  cells_.clear();
  for (PetscInt c : space.cells()) {
    Cell cell{c, {}};
    PetscCall(reader.Read(c, cell.corners.data()));
    for (int k = 0; k < corners_; ++k)
      for (int d = 0; d < D; ++d) {
        lo[d] = std::min(lo[d], cell.corners[D * k + d]);
        hi[d] = std::max(hi[d], cell.corners[D * k + d]);
      }
    cells_.push_back(cell);
  }
  for (int d = 0; d < 3; ++d)
    bounds_.lo[d] = d < D || cells_.empty() ? lo[d] : 0.0, bounds_.hi[d] = d < D || cells_.empty() ? hi[d] : 0.0;
  if (cells_.empty()) PetscFunctionReturn(0);
  first_point_ = cells_.front().point;
  index_of_point_.assign(cells_.back().point - first_point_ + 1, std::numeric_limits<std::size_t>::max());
  for (std::size_t i = 0; i < cells_.size(); ++i) index_of_point_[cells_[i].point - first_point_] = i;
  FillBins(lo, hi);
  PetscFunctionReturn(0);
}

void CellLocator::FillBins(const double* lo, const double* hi) {
  const int D = dim_;
  // About one cell a bin.
  double measure = hi[0] - lo[0];
  for (int d = 1; d < D; ++d) measure *= hi[d] - lo[d];
  const double per_cell = measure / static_cast<double>(cells_.size());
  bin_ = std::max(1e-300, D == 2 ? std::sqrt(per_cell) : std::cbrt(per_cell));
  bins_per_axis_ = {1, 1, 1};
  for (int d = 0; d < D; ++d) {
    origin_[d] = lo[d];
    bins_per_axis_[d] = std::max(1, static_cast<int>(std::ceil((hi[d] - lo[d]) / bin_)));
  }
  const auto [nx, ny, nz] = bins_per_axis_;
  bins_.assign(static_cast<std::size_t>(nx) * ny * nz, {});
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    double clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < corners_; ++k)
      for (int d = 0; d < D; ++d) {
        clo[d] = std::min(clo[d], cells_[i].corners[D * k + d]);
        chi[d] = std::max(chi[d], cells_[i].corners[D * k + d]);
      }
    int first[3] = {0, 0, 0}, last[3] = {0, 0, 0};
    for (int d = 0; d < D; ++d) {
      first[d] = std::clamp(static_cast<int>((clo[d] - origin_[d]) / bin_), 0, bins_per_axis_[d] - 1);
      last[d] = std::clamp(static_cast<int>((chi[d] - origin_[d]) / bin_), 0, bins_per_axis_[d] - 1);
    }
    for (int l = first[2]; l <= last[2]; ++l)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int k = first[0]; k <= last[0]; ++k) bins_[(static_cast<std::size_t>(l) * ny + j) * nx + k].push_back(i);
  }
}

ReferencePoint CellLocator::Map(const Cell& c, const ReferencePoint& r) const {
  return MapToCell(c.corners.data(), dim_, simplex_, r);
}

std::array<double, 9> CellLocator::MapJacobian(const Cell& c, const ReferencePoint& r) const {
  const int D = dim_;
  const auto& p = c.corners;
  std::array<double, 9> J{};
  if (simplex_) {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) J[D * i + j] = 0.5 * (p[D * (j + 1) + i] - p[i]);
    return J;
  }
  for (int k = 0; k < corners_; ++k) {
    double dn[3];  // ∂n_k/∂ξ_j
    for (int j = 0; j < D; ++j) {
      dn[j] = CornerSign(k, j) * (D == 2 ? 0.25 : 0.125);
      for (int d = 0; d < D; ++d)
        if (d != j) dn[j] *= CornerSign(k, d) > 0 ? 1 + r[d] : 1 - r[d];
    }
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) J[D * i + j] += dn[j] * p[D * k + i];
  }
  return J;
}

bool CellLocator::Inside(const Cell& c, const double* x, ReferencePoint* ref) const {
  const int D = dim_;
  ReferencePoint r = {0.0, 0.0, 0.0};
  if (simplex_) r = D == 2 ? ReferencePoint{-1.0 / 3.0, -1.0 / 3.0, 0.0} : ReferencePoint{-0.5, -0.5, -0.5};
  bool converged = false;
  // x's rounding: in a cell far thinner than its coordinates (the heat mesh's first
  // layers at a crack) it is more than 1e-12 of the reference cell, so a residual
  // at that level counts as converged too.
  double magnitude = 0.0;
  for (int i = 0; i < D; ++i) magnitude = std::max(magnitude, std::abs(x[i]));
  for (int it = 0; it < 20 && !converged; ++it) {  // Newton on x(r) = x; one step for simplices
    const auto X = Map(c, r);
    double f[3], d[3], residual = 0.0;
    for (int i = 0; i < D; ++i) f[i] = X[i] - x[i], residual = std::max(residual, std::abs(f[i]));
    SolveJacobian(MapJacobian(c, r), f, D, d);
    double step = std::abs(d[0]);
    for (int i = 1; i < D; ++i) step += std::abs(d[i]);
    for (int i = 0; i < D; ++i) r[i] -= d[i];
    converged = step < 1e-12 || residual <= 1e-14 * magnitude;
  }
  *ref = r;
  // From a point well outside a multilinear cell Newton may wander and stop
  // inside the reference cell without having converged: such a cell does not hold the point.
  if (!converged && !simplex_) return false;
  return InReferenceCell(r.data(), D, simplex_, 1e-10);
}

void CellLocator::Locate(const double* x, PetscInt* cell, ReferencePoint* ref) const {
  *cell = -1;
  if (bins_.empty()) return;
  int index[3] = {0, 0, 0};
  for (int d = 0; d < dim_; ++d) {
    const int i = static_cast<int>(std::floor((x[d] - origin_[d]) / bin_));
    if (i > bins_per_axis_[d] || i < -1) return;  // a point on the far side of the box belongs to the last bin
    index[d] = std::clamp(i, 0, bins_per_axis_[d] - 1);
  }
  const std::size_t b =
      (static_cast<std::size_t>(index[2]) * bins_per_axis_[1] + index[1]) * bins_per_axis_[0] + index[0];
  for (std::size_t k : bins_[b])
    if (Inside(cells_[k], x, ref)) {
      *cell = cells_[k].point;
      return;
    }
}

void CellLocator::Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const {
  const double point[2] = {x, y};
  ReferencePoint r = {0.0, 0.0, 0.0};
  Locate(point, cell, &r);
  if (*cell >= 0) *ref = {r[0], r[1]};
}

std::array<double, 9> CellLocator::Jacobian(PetscInt cell, const ReferencePoint& ref) const {
  return MapJacobian(cells_[index_of_point_[cell - first_point_]], ref);
}

std::array<double, 4> CellLocator::Jacobian(PetscInt cell, const std::array<double, 2>& ref) const {
  const auto J = Jacobian(cell, ReferencePoint{ref[0], ref[1], 0.0});
  return {J[0], J[1], J[2], J[3]};
}

}  // namespace vibrotherm::fe

#include "vibrotherm/fe/cell_corners.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::fe {

std::vector<double> ReferenceCorners(int dim, bool simplex) {
  std::vector<double> corners;
  if (simplex) {
    for (int k = 0; k <= dim; ++k)
      for (int d = 0; d < dim; ++d) corners.push_back(k == d + 1 ? 1.0 : -1.0);
    return corners;
  }
  for (int k = 0; k < 1 << dim; ++k)
    for (int d = 0; d < dim; ++d) corners.push_back(CornerSign(k, d));
  return corners;
}

ReferencePoint MapToCell(const double* p, int D, bool simplex, const ReferencePoint& r) {
  ReferencePoint x = {0.0, 0.0, 0.0};
  if (simplex) {  // affine: x = p0 + Σ_d (p_{d+1} − p0)(ξ_d + 1)/2
    for (int i = 0; i < D; ++i) {
      x[i] = p[i];
      for (int d = 0; d < D; ++d) x[i] += 0.5 * (r[d] + 1) * (p[D * (d + 1) + i] - p[i]);
    }
    return x;
  }
  const int corners = 1 << D;
  double n[8] = {};  // multilinear: the corner's product of (1 ± ξ_d)/2
  for (int k = 0; k < corners; ++k) {
    n[k] = D == 2 ? 0.25 : 0.125;
    for (int d = 0; d < D; ++d) n[k] *= CornerSign(k, d) > 0 ? 1 + r[d] : 1 - r[d];
  }
  for (int i = 0; i < D; ++i) {
    x[i] = n[0] * p[i];
    for (int k = 1; k < corners; ++k) x[i] += n[k] * p[D * k + i];
  }
  return x;
}

CellCorners::CellCorners(DM dm, int dim, bool simplex)
    : dm_(dm), dim_(dim), corners_(simplex ? dim + 1 : 1 << dim), ref_(ReferenceCorners(dim, simplex)) {}

PetscErrorCode CellCorners::Read(PetscInt c, double* x) {
  PetscFunctionBeginUser;
  if (count_++ % 256 == 0 || order_.empty()) {
    PetscCall(DMPlexReferenceToCoordinates(dm_, c, corners_, ref_.data(), x));
    PetscCall(Learn(c, x));
    PetscFunctionReturn(0);
  }
  PetscScalar* v = nullptr;
  PetscInt n;
  PetscCall(Closure(c, &n, &v, false));
  for (int k = 0; k < corners_; ++k)
    for (int d = 0; d < dim_; ++d) x[dim_ * k + d] = PetscRealPart(v[dim_ * order_[k] + d]);
  PetscCall(Closure(c, &n, &v, true));
  PetscFunctionReturn(0);
}

PetscErrorCode CellCorners::Closure(PetscInt c, PetscInt* n, PetscScalar** v, bool restore) const {
  PetscFunctionBeginUser;
  DM cdm;
  PetscSection cs;
  Vec coords;
  PetscCall(DMGetCoordinateDM(dm_, &cdm));
  PetscCall(DMGetLocalSection(cdm, &cs));
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  if (restore) PetscCall(DMPlexVecRestoreClosure(cdm, cs, coords, c, n, v));
  else PetscCall(DMPlexVecGetClosure(cdm, cs, coords, c, n, v));
  PetscFunctionReturn(0);
}

PetscErrorCode CellCorners::Learn(PetscInt c, const double* x) {
  PetscFunctionBeginUser;
  const int D = dim_;
  PetscScalar* v = nullptr;
  PetscInt n;
  PetscCall(Closure(c, &n, &v, false));
  const int nv = static_cast<int>(n) / D;
  double scale = 0.0;  // the cell's coordinates: those near 0 carry rounding of that size
  for (int k = 0; k < D * corners_; ++k) scale = std::max(scale, std::abs(x[k]));
  std::vector<int> order(corners_, -1);
  for (int k = 0; k < corners_; ++k) {
    double best = INFINITY;
    for (int j = 0; j < nv; ++j) {
      double d2 = 0.0;
      for (int d = 0; d < D; ++d) d2 += std::pow(PetscRealPart(v[D * j + d]) - x[D * k + d], 2);
      if (d2 < best) best = d2, order[k] = j;
    }
    PetscCheck(std::sqrt(best) <= 1e-12 * scale, PETSC_COMM_SELF, PETSC_ERR_SUP,
               "cell %" PetscInt_FMT ": its corners are not its closure's coordinates (a curved or periodic mesh?)", c);
  }
  PetscCall(Closure(c, &n, &v, true));
  PetscCheck(order_.empty() || order == order_, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "cell %" PetscInt_FMT " maps its closure's vertices to other reference corners than the first cell", c);
  order_ = order;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::fe

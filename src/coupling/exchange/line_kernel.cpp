#include "vibrotherm/coupling/exchange/line_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::coupling {
namespace {

/// Coefficients of node k's basis in σ ∈ [0, ℓ]: φ = c0 + c1 σ + c2 σ².
std::array<double, 3> BasisCoefficients(int degree, int k, double ell) {
  if (degree == 1) return k == 0 ? std::array<double, 3>{1.0, -1.0 / ell, 0.0} : std::array<double, 3>{0.0, 1.0 / ell, 0.0};
  const double l2 = ell * ell;
  if (k == 0) return {1.0, -3.0 / ell, 2.0 / l2};
  if (k == 1) return {0.0, -1.0 / ell, 2.0 / l2};
  return {0.0, 4.0 / ell, -4.0 / l2};
}

/// erf(hi) − erf(lo) without cancellation when both lie on one side of 0.
double ErfDifference(double lo, double hi) {
  if (lo >= 0.0) return std::erfc(lo) - std::erfc(hi);
  if (hi <= 0.0) return std::erfc(-hi) - std::erfc(-lo);
  return std::erf(hi) - std::erf(lo);
}

}  // namespace

void LineKernel::Kernel(double tau, std::vector<double>* k) const {
  k->assign(cells_, 0.0);
  const double a = 4.0 * alpha_ * tau, sa = std::sqrt(a);
  for (const KernelSegment& g : segments_) {
    const double dx = g.p1[0] - g.p0[0], dy = g.p1[1] - g.p0[1], ell = std::hypot(dx, dy);
    const double rx = x_[0] - g.p0[0], ry = x_[1] - g.p0[1];
    const double sx = (rx * dx + ry * dy) / ell, d2 = std::max(rx * rx + ry * ry - sx * sx, 0.0);
    const double decay = std::exp(-d2 / a);
    if (decay == 0.0) continue;
    // Moments of exp(−u²/a) over u = σ − σx ∈ [lo, hi].
    const double lo = -sx, hi = ell - sx, e_lo = std::exp(-lo * lo / a), e_hi = std::exp(-hi * hi / a);
    const double m0 = 0.5 * std::sqrt(M_PI) * sa * ErfDifference(lo / sa, hi / sa);
    const double m1 = -0.5 * a * (e_hi - e_lo), m2 = 0.5 * a * (m0 - (hi * e_hi - lo * e_lo));
    for (int n = 0; n < (g.degree == 2 ? 3 : 2); ++n) {
      if (g.cell[n] < 0) continue;
      const auto c = BasisCoefficients(g.degree, n, ell);
      const double b0 = c[0] + c[1] * sx + c[2] * sx * sx, b1 = c[1] + 2.0 * c[2] * sx;
      // G's 1/(4πατ) = 1/(π a)
      (*k)[g.cell[n]] += decay * (b0 * m0 + b1 * m1 + c[2] * m2) / (M_PI * a * rho_c_);
    }
  }
}

void LineKernel::Build(const std::array<double, 2>& x, const std::vector<KernelSegment>& segments, int cells,
                       double alpha, double rho_c, double tau_max, int intervals) {
  static const double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                               0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                               0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  x_ = x;
  segments_ = segments;
  intervals_ = intervals;
  cells_ = cells;
  alpha_ = alpha;
  rho_c_ = rho_c;
  s_max_ = std::sqrt(tau_max);
  h_ = s_max_ / intervals;
  const int points = intervals + 1;
  value_.assign(static_cast<std::size_t>(cells) * points, 0.0);
  slope_.assign(value_.size(), 0.0);
  std::vector<double> k;
  for (int i = 0; i < points; ++i) {
    // dΦ/ds = 2s K(s²) is finite at s = 0 (K ~ 1/s on the line): take it just above.
    const double s = i == 0 ? 1e-6 * h_ : i * h_;
    Kernel(s * s, &k);
    for (int c = 0; c < cells; ++c) slope_[i * cells + c] = h_ * 2.0 * s * k[c];
    if (i == 0) continue;
    for (int q = 0; q < 8; ++q) {  // Φ(s_i) = Φ(s_{i−1}) + ∫ 2s K(s²) ds over the grid cell
      const double sq = (i - 0.5) * h_ + 0.5 * h_ * gx[q];
      Kernel(sq * sq, &k);
      for (int c = 0; c < cells; ++c) value_[i * cells + c] += 0.5 * h_ * gw[q] * 2.0 * sq * k[c];
    }
    for (int c = 0; c < cells; ++c) value_[i * cells + c] += value_[(i - 1) * cells + c];
  }
}

namespace {

/// Grid cell i and the cubic Hermite weights (value, slope at i; value, slope at i + 1) at s = √τ.
int HermiteWeights(double tau, double h, int intervals, double w[4]) {
  const double x = std::min(std::sqrt(std::max(tau, 0.0)) / h, static_cast<double>(intervals));
  const int i = std::min(static_cast<int>(x), intervals - 1);
  const double t = x - i, t2 = t * t, t3 = t2 * t;
  w[0] = 2 * t3 - 3 * t2 + 1, w[1] = t3 - 2 * t2 + t, w[2] = -2 * t3 + 3 * t2, w[3] = t3 - t2;
  return i;
}

}  // namespace

double LineKernel::Phi(int cell, double tau) const {
  double w[4];
  const std::size_t i = static_cast<std::size_t>(HermiteWeights(tau, h_, intervals_, w)) * cells_ + cell;
  return w[0] * value_[i] + w[1] * slope_[i] + w[2] * value_[i + cells_] + w[3] * slope_[i + cells_];
}

double LineKernel::Combine(const double* weight, double tau) const {
  double w[4];
  const std::size_t i = static_cast<std::size_t>(HermiteWeights(tau, h_, intervals_, w)) * cells_;
  const double *v0 = &value_[i], *m0 = &slope_[i], *v1 = v0 + cells_, *m1 = m0 + cells_;
  double sum = 0.0;
  for (int c = 0; c < cells_; ++c) sum += weight[c] * (w[0] * v0[c] + w[1] * m0[c] + w[2] * v1[c] + w[3] * m1[c]);
  return sum;
}

}  // namespace vibrotherm::coupling

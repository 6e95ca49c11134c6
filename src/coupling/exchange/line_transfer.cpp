#include "vibrotherm/coupling/exchange/line_transfer.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::coupling {

std::array<double, 3> ElementBasis(int degree, double t) {
  if (degree == 1) return {1.0 - t, t, 0.0};
  return {(1.0 - t) * (1.0 - 2.0 * t), t * (2.0 * t - 1.0), 4.0 * t * (1.0 - t)};
}

namespace {

/// Adds ∫ over [a, b] of ψ_target φ_source (3-point Gauss: exact to degree 5).
void AddOverlap(const CrackElement& target, const CrackElement& source, double a, double b,
                std::vector<TransferEntry>* out) {
  static const double x[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double ds_dxi = source.length / (source.xi1 - source.xi0);
  const int nt = target.degree == 2 ? 3 : 2, ns = source.degree == 2 ? 3 : 2;
  double m[3][3] = {};
  for (int q = 0; q < 3; ++q) {
    const double xi = 0.5 * (a + b) + 0.5 * (b - a) * x[q], weight = 0.5 * (b - a) * w[q] * ds_dxi;
    const auto psi = ElementBasis(target.degree, (xi - target.xi0) / (target.xi1 - target.xi0));
    const auto phi = ElementBasis(source.degree, (xi - source.xi0) / (source.xi1 - source.xi0));
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < ns; ++j) m[i][j] += weight * psi[i] * phi[j];
  }
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < ns; ++j)
      if (target.node[i] >= 0 && source.node[j] >= 0 && m[i][j] != 0.0)
        out->push_back({target.node[i], source.node[j], m[i][j]});
}

}  // namespace

std::vector<TransferEntry> LineTransferEntries(const std::vector<CrackElement>& targets,
                                               const std::vector<CrackElement>& sources) {
  std::vector<TransferEntry> entries;
  for (const CrackElement& t : targets)
    for (const CrackElement& s : sources) {
      if (s.crack != t.crack) continue;
      const double a = std::max(t.xi0, s.xi0), b = std::min(t.xi1, s.xi1);
      if (b > a) AddOverlap(t, s, a, b, &entries);
    }
  return entries;
}

}  // namespace vibrotherm::coupling

#include "vibrotherm/heat/heat_element.hpp"

#include <algorithm>

namespace vibrotherm::heat {

void ElementHeatMatrices(const fe::CellQuadrature& q, double rc, double k, bool lumped, double* Me, double* Ke) {
  const int Nb = q.nodes, D = q.dim;
  std::fill(Me, Me + Nb * Nb, 0.0);
  std::fill(Ke, Ke + Nb * Nb, 0.0);
  for (int p = 0; p < q.points; ++p) {
    const double* phi = q.value + p * Nb;
    const double* g = &q.grad[p * Nb * D];
    for (int a = 0; a < Nb; ++a)
      for (int b = 0; b < Nb; ++b) {
        Me[lumped ? a * Nb + a : a * Nb + b] += q.weight[p] * rc * phi[a] * phi[b];
        Ke[a * Nb + b] += q.weight[p] * k * fe::GradientDot(g + D * a, g + D * b, D);
      }
  }
}

}  // namespace vibrotherm::heat

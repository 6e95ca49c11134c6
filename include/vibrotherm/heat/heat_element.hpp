// The element matrices of transient conduction on a LagrangeSpace cell, in any
// dimension (the gradients' length is q.dim):
//
//   M_ab = ∫ ρ c_p φ_a φ_b   (lumped: row sums on the diagonal)
//   K_ab = ∫ k ∇φ_a·∇φ_b
#pragma once

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::heat {

/// Me, Ke (nodes × nodes, row-major, closure order) of one cell from its
/// quadrature data; rc = ρ c_p, k the conductivity.
void ElementHeatMatrices(const fe::CellQuadrature& q, double rc, double k, bool lumped, double* Me, double* Ke);

}  // namespace vibrotherm::heat

// Friction heat as a line density, moved exactly from the wave mesh's crack to
// the heat mesh's crack (plain C++, no PETSc: unit-tested alone).
//
// Along a crack, ξ ∈ [0, 1] is the fraction of its length. The wave side
// defines a line density q(ξ) = Σ_c q_c φ_c(ξ): q_c the friction power per unit
// area of contact cell c over the exchange, φ_c the wave element's face basis
// (degree 1: hats; degree 2: quadratics with the mid-side node), so that
// ∫ q ds = Σ_c w_c q_c with w_c = ∫ φ_c ds the cell's tributary length: the
// energy the crack law dissipated, exactly. The heat load is
//   Q_h = ∫ ψ_h q ds = Σ_c T_hc q_c,   T_hc = ∫ ψ_h φ_c ds
// with ψ_h the heat basis. Products of two pieces of degree ≤ 2 are integrated
// exactly (3-point Gauss per overlap of a heat and a wave element); the heat
// basis sums to one, so Σ_h T_hc = w_c: heat deposited = energy dissipated.
#pragma once

#include <array>
#include <vector>

namespace vibrotherm::coupling {

/// A straight piece [ξ0, ξ1] of a crack carrying a 1D Lagrange element.
struct CrackElement {
  int crack = 0;
  double xi0 = 0.0, xi1 = 0.0;  ///< ξ0 < ξ1
  double length = 0.0;          ///< physical length [m]
  int degree = 1;               ///< 1 or 2
  /// Owner index of the node at ξ0, at ξ1, and (degree 2) at the middle; −1: no unknown there.
  std::array<long, 3> node = {-1, -1, -1};
};

struct TransferEntry {
  long row, col;  ///< target (heat) node, source (contact cell)
  double value;   ///< ∫ ψ_row φ_col ds [m]
};

/// Lagrange basis of an element at t = (ξ − ξ0)/(ξ1 − ξ0), in node order (ξ0, ξ1, middle).
std::array<double, 3> ElementBasis(int degree, double t);

/// T_hc for every overlapping pair of a target and a source element of the
/// same crack, measured with the source's length (so Σ_h T_hc = ∫ φ_c ds
/// exactly where the targets tile the crack). Entries are not merged.
std::vector<TransferEntry> LineTransferEntries(const std::vector<CrackElement>& targets,
                                               const std::vector<CrackElement>& sources);

}  // namespace vibrotherm::coupling

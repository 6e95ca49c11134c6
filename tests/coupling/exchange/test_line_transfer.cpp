// Requirement: friction heat moves from the wave mesh's crack to the heat
// mesh's crack exactly — every contact cell's energy arrives whole (Σ_h T_hc =
// its tributary length), a uniform density gives the heat basis' own line
// load, and a density linear along the crack is integrated exactly — whatever
// the two partitions of the crack and the degrees of the two meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "vibrotherm/coupling/exchange/line_transfer.hpp"

namespace vibrotherm::coupling {
namespace {

/// Elements tiling [0, 1] of a crack of length L at random breakpoints; nodes numbered
/// consecutively from `first` (end nodes shared, mid-side nodes after them).
std::vector<CrackElement> Partition(int crack, double L, int n, int degree, long first, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.2, 1.0);
  std::vector<double> cuts{0.0};
  for (int i = 0; i < n; ++i) cuts.push_back(cuts.back() + u(rng));
  std::vector<CrackElement> out;
  for (int i = 0; i < n; ++i) {
    CrackElement e;
    e.crack = crack;
    e.xi0 = i == 0 ? 0.0 : cuts[i] / cuts.back();
    e.xi1 = i + 1 == n ? 1.0 : cuts[i + 1] / cuts.back();
    e.length = (e.xi1 - e.xi0) * L;
    e.degree = degree;
    e.node = {first + i, first + i + 1, degree == 2 ? first + n + 1 + i : -1};
    out.push_back(e);
  }
  return out;
}

/// ∫φ_node ds of every node: the lumped weights (P1: ℓ/2 per end; P2: ℓ/6 per end, 4ℓ/6 mid).
std::map<long, double> Weights(const std::vector<CrackElement>& elements) {
  std::map<long, double> w;
  for (const CrackElement& e : elements) {
    const double end = e.degree == 1 ? 0.5 : 1.0 / 6.0;
    w[e.node[0]] += end * e.length;
    w[e.node[1]] += end * e.length;
    if (e.degree == 2) w[e.node[2]] += 4.0 / 6.0 * e.length;
  }
  return w;
}

struct Degrees {
  int source, target;
};

class LineTransfer : public ::testing::TestWithParam<Degrees> {};

TEST_P(LineTransfer, EveryCellsEnergyArrivesWhole) {
  std::mt19937 rng(7);
  const double L = 0.02;
  const auto sources = Partition(0, L, 13, GetParam().source, 0, rng);
  const auto targets = Partition(0, L, 37, GetParam().target, 1000, rng);
  std::map<long, double> arrived;
  for (const TransferEntry& t : LineTransferEntries(targets, sources)) arrived[t.col] += t.value;
  for (const auto& [cell, w] : Weights(sources)) EXPECT_NEAR(arrived[cell], w, 1e-15 * L) << "cell " << cell;
}

TEST_P(LineTransfer, UniformDensityGivesTheTargetsLineLoad) {
  std::mt19937 rng(11);
  const double L = 0.013;
  const auto sources = Partition(0, L, 9, GetParam().source, 0, rng);
  const auto targets = Partition(0, L, 23, GetParam().target, 500, rng);
  std::map<long, double> load;
  for (const TransferEntry& t : LineTransferEntries(targets, sources)) load[t.row] += t.value;  // q = 1 everywhere
  for (const auto& [node, w] : Weights(targets)) EXPECT_NEAR(load[node], w, 1e-15 * L) << "heat node " << node;
}

TEST_P(LineTransfer, LinearDensityIsIntegratedExactly) {
  // q(s) = s: the Lagrange interpolant is exact for both degrees; the load of a
  // target node is ∫ ψ s ds, closed form per element.
  std::mt19937 rng(3);
  const double L = 0.02;
  const auto sources = Partition(0, L, 7, GetParam().source, 0, rng);
  const auto targets = Partition(0, L, 19, GetParam().target, 100, rng);
  std::map<long, double> q;  // nodal values of s
  for (const CrackElement& e : sources) {
    q[e.node[0]] = e.xi0 * L;
    q[e.node[1]] = e.xi1 * L;
    if (e.degree == 2) q[e.node[2]] = 0.5 * (e.xi0 + e.xi1) * L;
  }
  std::map<long, double> load, exact;
  for (const TransferEntry& t : LineTransferEntries(targets, sources)) load[t.row] += t.value * q[t.col];
  for (const CrackElement& e : targets) {
    const double a = e.xi0 * L, l = e.length;  // s = a + l τ on the element
    if (e.degree == 1) {
      exact[e.node[0]] += l * (a / 2 + l / 6);
      exact[e.node[1]] += l * (a / 2 + l / 3);
    } else {
      exact[e.node[0]] += l * a / 6;
      exact[e.node[1]] += l * (a + l) / 6;
      exact[e.node[2]] += 4 * l / 6 * (a + l / 2);
    }
  }
  for (const auto& [node, value] : exact) EXPECT_NEAR(load[node], value, 1e-15 * L * L) << "heat node " << node;
}

INSTANTIATE_TEST_SUITE_P(Degrees, LineTransfer,
                         ::testing::Values(Degrees{1, 1}, Degrees{2, 1}, Degrees{1, 2}, Degrees{2, 2}));

TEST(LineTransferCracks, CracksDoNotExchangeHeat) {
  std::mt19937 rng(5);
  const auto sources = Partition(0, 0.01, 5, 2, 0, rng);
  auto targets = Partition(1, 0.01, 5, 1, 100, rng);
  EXPECT_TRUE(LineTransferEntries(targets, sources).empty());
}

}  // namespace
}  // namespace vibrotherm::coupling

// Requirement: contact-cell geometry follows PHYSICS.md §3.1 whatever order the
// facets come in — the tangent runs from a crack's first facet to its last, the
// normal is the tangent turned by +90°, every facet's tangent points the
// crack's way, a crack's tributary lengths sum to its length (degree 1: vertex
// nodes; degree 2: vertex and mid-side nodes, Simpson's 1/6, 4/6, 1/6), and ξ
// runs from 0 to 1 along the crack.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "vibrotherm/interface/contact_geometry.hpp"

namespace vibrotherm::interface {
namespace {

/// A straight crack cut into n facets of random lengths, ids in order along it,
/// each facet's end points in random order, the facets shuffled.
std::vector<CrackFacetGeometry> Crack(int crack, long first_id, Vec2 start, Vec2 end, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.5, 1.5);
  std::vector<double> cut{0.0};
  for (int i = 0; i < n; ++i) cut.push_back(cut.back() + u(rng));
  std::vector<CrackFacetGeometry> out;
  for (int i = 0; i < n; ++i) {
    auto at = [&](double f) { return Vec2{start[0] + f * (end[0] - start[0]), start[1] + f * (end[1] - start[1])}; };
    CrackFacetGeometry g{first_id + i, crack, at(cut[i] / cut.back()), at(cut[i + 1] / cut.back())};
    if (rng() % 2) std::swap(g.p0, g.p1);
    out.push_back(g);
  }
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

double Dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

class ContactGeometryDegrees : public ::testing::TestWithParam<int> {};

TEST_P(ContactGeometryDegrees, FollowsTheConventions) {
  std::mt19937 rng(42);
  const Vec2 a0{0.01, 0.02}, a1{0.03, 0.027}, b0{0.04, 0.09}, b1{0.02, 0.06};  // crack b runs to smaller x
  auto facets = Crack(0, 0, a0, a1, 17, rng);
  const auto b = Crack(1, 17, b0, b1, 11, rng);
  facets.insert(facets.end(), b.begin(), b.end());
  const ContactGeometry g(facets, GetParam());
  for (int crack : {0, 1}) {
    const Vec2 start = crack == 0 ? a0 : b0, end = crack == 0 ? a1 : b1;
    const double L = std::hypot(end[0] - start[0], end[1] - start[1]);
    const Vec2 s = {(end[0] - start[0]) / L, (end[1] - start[1]) / L};
    const CrackFrame& fr = g.frame(crack);
    EXPECT_NEAR(fr.length, L, 1e-15);
    EXPECT_NEAR(Dot(fr.direction, s), 1.0, 1e-12) << "tangent from the first facet to the last";
    EXPECT_NEAR(g.xi(crack, start), 0.0, 1e-12);
    EXPECT_NEAR(g.xi(crack, end), 1.0, 1e-12);
    const Vec2 n = ContactGeometry::normal(fr.direction);
    EXPECT_NEAR(fr.direction[0] * n[1] - fr.direction[1] * n[0], 1.0, 1e-15) << "(s, n) right handed";
    double weights = 0.0;
    std::vector<std::pair<double, double>> seen;  // vertex nodes counted once
    for (const CrackFacetGeometry& f : facets) {
      if (f.crack != crack) continue;
      EXPECT_NEAR(Dot(g.tangent(f), s), 1.0, 1e-12) << "facet " << f.id;
      if (GetParam() == 2) weights += g.middle(f).weight;
      for (const Vec2& p : {f.p0, f.p1}) {
        if (std::find(seen.begin(), seen.end(), std::make_pair(p[0], p[1])) != seen.end()) continue;
        seen.emplace_back(p[0], p[1]);
        const NodeGeometry node = g.vertex(p);
        weights += node.weight;
        EXPECT_NEAR(Dot(node.tangent, s), 1.0, 1e-12);
      }
    }
    EXPECT_NEAR(weights, L, 1e-14) << "tributary lengths of crack " << crack;
  }
}

INSTANTIATE_TEST_SUITE_P(Degree, ContactGeometryDegrees, ::testing::Values(1, 2));

}  // namespace
}  // namespace vibrotherm::interface

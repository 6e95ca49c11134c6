// Requirement (issue 41): a generated 2D mesh is mirror-symmetric across each crack within
// its band: every cell there has its mirror image across the crack's line (the same
// vertices, reflected, to rounding), and the band is planned to fit the specimen: past an
// inner tip by its width, ending on an outer edge the crack meets at a right angle, short
// of an inclined one, narrowed near another crack, none (and said) where two elements do
// not fit. The control: with -mesh_crack_mirror off (the default) almost no cell near
// the paper crack has its mirror image, so the check can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "vibrotherm/mesh/crack_mirror.hpp"
#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::testing {
namespace {

using mesh::CrackMirror;
using P = CrackMirror::P;

mesh::SpecimenGeometry Box(std::vector<mesh::Crack> cracks, double h = 0.004, double h_crack = 0.001) {
  mesh::SpecimenGeometry g;
  g.width = 0.05, g.height = 0.1, g.h = h, g.h_crack = h_crack, g.grading = 0.3;
  g.crack_mirror_width = -1.0;  // -mesh_crack_mirror on
  g.cracks = std::move(cracks);
  return g;
}

mesh::Crack Crack(double x, double y, double length, double angle) {
  mesh::Crack c;
  c.x = x, c.y = y, c.length = length, c.angle_deg = angle;
  return c;
}

mesh::SpecimenGeometry Paper() { return Box({Crack(0.025, 0.05, 0.02, 20)}, 0.002, 0.0005); }

/// A cell as the sorted list of its vertices' positions, rounded to 1e-12 m.
using CellKey = std::vector<std::array<long long, 2>>;
CellKey Key(const std::vector<P>& corners) {
  CellKey key;
  for (const P& p : corners) key.push_back({std::llround(p[0] * 1e12), std::llround(p[1] * 1e12)});
  std::sort(key.begin(), key.end());
  return key;
}

struct Symmetry {
  int cells = 0, mirrored = 0;  ///< cells with their centroid in the band; of them, those with a mirror image
};

/// Within the band of `band` (its planned rectangle, shrunk by 1e-9 m), which cells have their mirror image.
Symmetry Check(const mesh::MeshData& m, const CrackMirror& band) {
  std::map<CellKey, int> cells;
  std::vector<std::vector<P>> corners(m.cell_count());
  for (int c = 0; c < m.cell_count(); ++c) {
    for (int k = 0; k < m.corners; ++k) {
      const int v = m.cells[m.corners * c + k];
      corners[c].push_back({m.coords[2 * v], m.coords[2 * v + 1]});
    }
    cells[Key(corners[c])] = c;
  }
  const P d = {band.normal[1], -band.normal[0]};
  const double from = (band.e0[0] - band.p0[0]) * d[0] + (band.e0[1] - band.p0[1]) * d[1];
  const double to = (band.e1[0] - band.p0[0]) * d[0] + (band.e1[1] - band.p0[1]) * d[1];
  Symmetry s;
  for (int c = 0; c < m.cell_count(); ++c) {
    P x = {0.0, 0.0};
    for (const P& p : corners[c]) x[0] += p[0] / m.corners, x[1] += p[1] / m.corners;
    const P r = {x[0] - band.p0[0], x[1] - band.p0[1]};
    const double along = r[0] * d[0] + r[1] * d[1], across = r[0] * band.normal[0] + r[1] * band.normal[1];
    if (along < from + 1e-9 || along > to - 1e-9 || std::abs(across) > band.width - 1e-9) continue;
    ++s.cells;
    std::vector<P> image;
    for (const P& p : corners[c]) image.push_back(band.reflect(p));
    s.mirrored += cells.count(Key(image));
  }
  return s;
}

/// Every planned band of g's generated mesh: all its cells mirrored, and the band not empty.
void ExpectMirrored(const mesh::SpecimenGeometry& g, std::size_t bands) {
  const mesh::CrackMirrorPlan plan = mesh::PlanCrackMirror(g, mesh::DefaultMirrorWidth(g));
  ASSERT_EQ(plan.bands.size(), bands);
  const mesh::MeshData m = mesh::generate_specimen_mesh(g);
  for (const CrackMirror& band : plan.bands) {
    const Symmetry s = Check(m, band);
    EXPECT_GT(s.cells, 20) << "crack " << band.crack + 1;
    EXPECT_EQ(s.mirrored, s.cells) << "crack " << band.crack + 1 << ": cells without their mirror image";
  }
}

TEST(CrackMirror, PaperCrackIsMirrored) { ExpectMirrored(Paper(), 1); }

TEST(CrackMirror, WithoutTheBandThePaperMeshIsNot) {
  mesh::SpecimenGeometry g = Paper();
  const CrackMirror band = mesh::PlanCrackMirror(g, mesh::DefaultMirrorWidth(g)).bands.at(0);
  g.crack_mirror_width = 0.0;
  const Symmetry s = Check(mesh::generate_specimen_mesh(g), band);
  EXPECT_LT(s.mirrored, 0.05 * s.cells) << s.mirrored << " of " << s.cells;
}

TEST(CrackMirror, ThreeCracksQuadsAndTriangles) {
  mesh::SpecimenGeometry g = Box({Crack(0.015, 0.025, 0.01, 0), Crack(0.03, 0.05, 0.015, 45), Crack(0.02, 0.08, 0.012, -30)});
  ExpectMirrored(g, 3);
  g.quads = false;
  ExpectMirrored(g, 3);
}

TEST(CrackMirror, CracksEndingOnEdges) {
  ExpectMirrored(Box({Crack(0.01, 0.05, 0.02, 0)}), 1);   // from the left edge, at a right angle
  ExpectMirrored(Box({Crack(0.025, 0.05, 0.05, 0)}), 1);  // across the whole width
  ExpectMirrored(Box({Crack(0.015 * std::cos(M_PI / 6), 0.05, 0.03, 30)}), 1);  // from the left edge, inclined
}

TEST(CrackMirror, BandPlan) {
  const mesh::SpecimenGeometry paper = Paper();
  const double w = mesh::DefaultMirrorWidth(paper);
  EXPECT_NEAR(w, (0.002 - 0.0005) / 0.3, 1e-15);
  const CrackMirror inner = mesh::PlanCrackMirror(paper, w).bands.at(0);
  const double past0 = std::hypot(inner.e0[0] - inner.p0[0], inner.e0[1] - inner.p0[1]);
  const double past1 = std::hypot(inner.e1[0] - inner.p1[0], inner.e1[1] - inner.p1[1]);
  EXPECT_NEAR(past0, w, 1e-12);  // past both inner tips by the width
  EXPECT_NEAR(past1, w, 1e-12);
  EXPECT_NEAR(inner.width, w, 1e-15);
  const P probe = {0.03, 0.07};
  const P twice = inner.reflect(inner.reflect(probe));
  EXPECT_NEAR(twice[0], probe[0], 1e-15);
  EXPECT_NEAR(twice[1], probe[1], 1e-15);

  const CrackMirror right = mesh::PlanCrackMirror(Box({Crack(0.01, 0.05, 0.02, 0)}), 0.01).bands.at(0);
  EXPECT_EQ(right.e0, right.p0);  // the left edge is the band's end

  const CrackMirror inclined =
      mesh::PlanCrackMirror(Box({Crack(0.015 * std::cos(M_PI / 6), 0.05, 0.03, 30)}), 0.01).bands.at(0);
  EXPECT_NEAR(inclined.p0[0], 0.0, 1e-12);
  EXPECT_GT(inclined.e0[0], inclined.p0[0] + 0.005);  // short of the edge: the corners stay inside
  for (const P& q : {inclined.upper()[0], inclined.lower()[0]}) EXPECT_GE(q[0], 0.001 - 1e-12);

  // Two parallel cracks 6 mm apart: the second band is narrowed to keep an element from the first.
  const mesh::CrackMirrorPlan two = mesh::PlanCrackMirror(Box({Crack(0.025, 0.04, 0.01, 0), Crack(0.025, 0.046, 0.01, 0)}), 0.01);
  ASSERT_EQ(two.bands.size(), 2u);
  EXPECT_LE(two.bands[0].width + two.bands[1].width, 0.006 - 0.001 + 1e-12);

  // No room for two elements on either side: none, and said.
  const mesh::CrackMirrorPlan none = mesh::PlanCrackMirror(Box({Crack(0.025, 0.0015, 0.01, 0)}), 0.01);
  EXPECT_TRUE(none.bands.empty());
  ASSERT_EQ(none.why.size(), 1u);
  EXPECT_NE(none.why[0].find("crack 1"), std::string::npos);
  EXPECT_TRUE(mesh::PlanCrackMirror(Paper(), 0.0).bands.empty());
}

}  // namespace
}  // namespace vibrotherm::testing

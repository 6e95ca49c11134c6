// Requirement (issue 26, item 1): a transducer patch on a face of a 3D box has grid
// lines on its bounds (box_patch_grid.cpp):
//  - AlignNode moves the nearest free node (the others between its fixed neighbours
//    stretched, fixed ones untouched), keeps a fixed node within a third of a cell,
//    splits a cell whose two ends are fixed; in a grid nested in a coarser one it moves
//    only the coarser grid's lines, and the nesting stays;
//  - on every face, for a crack sheared into a horizontal (20°) and a vertical (70°)
//    grid plane, each bound is the physical position of a grid line of that face (on a
//    face the shear moves, through its inverse), except along the sheared axis of the
//    front and back faces; the crack keeps its cells.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vibrotherm/mesh/box_grid.hpp"

namespace vibrotherm::testing {
namespace {

TEST(AlignNode, MovesSnapsOrSplits) {
  std::vector<double> x = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  std::vector<int> fixed = {0, 5};
  EXPECT_DOUBLE_EQ(mesh::AlignNode(&x, &fixed, 2.3, 1e-12), 2.3);  // node 2 moves, 1 and 3..4 stretch
  EXPECT_DOUBLE_EQ(x[2], 2.3);
  EXPECT_DOUBLE_EQ(x[1], 2.3 / 2.0);
  EXPECT_DOUBLE_EQ(x[0], 0.0);
  EXPECT_DOUBLE_EQ(x[5], 5.0);
  EXPECT_EQ(fixed.back(), 2);
  const double node3 = x[3];
  EXPECT_DOUBLE_EQ(mesh::AlignNode(&x, &fixed, 2.3 + 0.2 * (node3 - 2.3), 1e-12), 2.3);  // node 2 fixed: snapped
  EXPECT_EQ(x.size(), 6u);
  std::vector<double> y = {0.0, 1.0, 2.0};
  std::vector<int> ends = {0, 1, 2};
  EXPECT_DOUBLE_EQ(mesh::AlignNode(&y, &ends, 0.5, 1e-12), 0.5);  // both ends fixed: a new node
  EXPECT_EQ(y, (std::vector<double>{0.0, 0.5, 1.0, 2.0}));
  EXPECT_EQ(ends, (std::vector<int>{0, 2, 3, 1}));
}

TEST(AlignNode, MovesOnlyTheCoarserGridsLinesInANestedGrid) {
  // A grid halving cells of 2 (its even nodes are the coarser grid's lines): 3.3 lies
  // between lines 2 and 4; line 4 moves (node 3, nearer, is no line) and every node
  // between the fixed ones stretches, so the halves stay halves.
  std::vector<double> x = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  std::vector<int> fixed = {0, 8};
  const auto even = [](int i) { return i % 2 == 0; };
  EXPECT_DOUBLE_EQ(mesh::AlignNode(&x, &fixed, 3.3, 1e-12, even), 3.3);
  EXPECT_DOUBLE_EQ(x[4], 3.3);
  for (int i = 1; i < 8; i += 2) EXPECT_NEAR(x[i], 0.5 * (x[i - 1] + x[i + 1]), 1e-15) << "node " << i;
  // Within a third of the coarser cell of a fixed line, the fixed line is the bound.
  EXPECT_DOUBLE_EQ(mesh::AlignNode(&x, &fixed, 3.3 + 0.3 * (x[6] - 3.3), 1e-12, even), 3.3);
}

mesh::SpecimenGeometry PatchBlock(double angle, mesh::Side side) {
  mesh::SpecimenGeometry g;
  g.width = 0.02, g.height = 0.02, g.depth = 0.01;
  g.h = 0.002, g.h_crack = 0.001;
  g.edges[static_cast<int>(mesh::Side::Top)] = mesh::EdgeKind::Free;
  mesh::Crack c;
  c.x = 0.01, c.y = 0.01, c.z = 0.005, c.length = 0.006, c.width = 0.004, c.angle_deg = angle;
  g.cracks = {c};
  const auto axes = mesh::face_axes(side);
  g.patch.on = true, g.patch.side = side;
  g.patch.center = 0.43 * g.extent(axes[0]), g.patch.width = 0.37 * g.extent(axes[0]);
  g.patch.center2 = 0.61 * g.extent(axes[1]), g.patch.width2 = 0.29 * g.extent(axes[1]);
  return g;
}

class BoxPatch : public ::testing::TestWithParam<double> {};

TEST_P(BoxPatch, BoundsAreGridLines) {
  const double angle = GetParam();
  for (int s = 0; s < 6; ++s) {
    const auto side = static_cast<mesh::Side>(s);
    const mesh::SpecimenGeometry g = PatchBlock(angle, side);
    const mesh::BoxGrid grid(g);
    EXPECT_EQ(grid.crack_cells(0), 6);
    EXPECT_EQ(grid.crack_cells(1), 4);
    EXPECT_TRUE(grid.patch_snaps().empty()) << mesh::to_string(side);
    const int n = mesh::face_normal_axis(side);
    const bool far = side == mesh::Side::Top || side == mesh::Side::Right || side == mesh::Side::Front;
    const auto axes = mesh::face_axes(side);
    const int sheared = std::abs(std::cos(angle * M_PI / 180.0)) < std::sqrt(0.5) ? 0 : 1;
    for (int k = 0; k < 2; ++k) {
      const int a = axes[k], other = axes[1 - k];
      if (n == 2 && a == sheared) continue;  // front, back: bent lines (the centroid rule)
      for (double bound : g.patch.bounds(k)) {
        bool found = false;
        for (int i = 0; i <= grid.cells(a); ++i) {
          std::array<double, 3> index{};
          index[n] = far ? grid.cells(n) : 0;
          index[a] = i;
          index[other] = grid.cells(other) / 2;
          found = found || std::abs(grid.position(index)[a] - bound) < 1e-12;
        }
        EXPECT_TRUE(found) << mesh::to_string(side) << " axis " << a << " bound " << bound;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Angles, BoxPatch, ::testing::Values(20.0, 70.0));

}  // namespace
}  // namespace vibrotherm::testing

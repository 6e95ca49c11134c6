// Requirement (issue 26, first 3D scene): the 3D box specimen's mesh (box_grid,
// box_mesher). For an inclined crack sheared into a horizontal grid plane (20°) and
// into a vertical one (70°):
//  - the hexahedra fill the box: positive volumes summing to W·H·D;
//  - every outer face lies on its side of the box and carries its kind;
//  - the crack's faces (-crack_length and -crack_width over -mesh_h_crack of them)
//    lie in the crack plane through its centre, with its normal, and their areas
//    sum to length × width;
//  - the split adds exactly one cohesive cell per crack face;
//  - the friction heat's sub-squares per wave crack face nest the heat grid's crack
//    lines (every heat line on a sub-square edge) whenever 16 a side suffice;
//  - an elliptical crack (-crack_shape ellipse) is the staircase of the wave faces whose
//    centres lie in the ellipse (counted independently here), within 3 % of its area,
//    split with one cohesive cell per face; the heat grid's halves tile it exactly (4
//    heat faces per wave face); the distance to it is the distance to the elliptical
//    disc (sampled independently).
// Bad geometry is refused naming the option.
#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "vibrotherm/mesh/box_grid.hpp"
#include "vibrotherm/mesh/box_mesher.hpp"
#include "vibrotherm/mesh/box_specimen.hpp"
#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::testing {
namespace {

mesh::SpecimenGeometry Block(double angle) {
  mesh::SpecimenGeometry g;
  g.width = 0.02, g.height = 0.02, g.depth = 0.01;
  g.h = 0.002, g.h_crack = 0.001;
  g.edges[static_cast<int>(mesh::Side::Top)] = mesh::EdgeKind::Source;
  g.depth_edges = {mesh::EdgeKind::Free, mesh::EdgeKind::Roller};
  mesh::Crack c;
  c.x = 0.01, c.y = 0.01, c.z = 0.005, c.length = 0.006, c.width = 0.004, c.angle_deg = angle;
  g.cracks = {c};
  return g;
}

class BoxSpecimen : public ::testing::TestWithParam<double> {};

TEST_P(BoxSpecimen, FillsTheBoxAndLabelsThePlanarCrack) {
  const mesh::SpecimenGeometry g = Block(GetParam());
  const mesh::BoxGrid grid(g);
  DM dm;
  PetscInt crack_faces;
  ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, grid, &dm, &crack_faces), 0);
  EXPECT_EQ(crack_faces, 6 * 4);
  PetscInt cStart, cEnd, fStart, fEnd;
  DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd);
  double volume = 0.0, smallest = INFINITY;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscReal v, centre[3];
    DMPlexComputeCellGeometryFVM(dm, c, &v, centre, nullptr);
    volume += v, smallest = std::min(smallest, v);
  }
  EXPECT_GT(smallest, 0.0);
  EXPECT_NEAR(volume, g.width * g.height * g.depth, 1e-12 * volume);
  const double t = GetParam() * M_PI / 180.0, n[3] = {-std::sin(t), std::cos(t), 0.0};
  const double size[3] = {g.width, g.height, g.depth};
  DMLabel crack, side;
  DMGetLabel(dm, mesh::labels::crack, &crack);
  DMGetLabel(dm, mesh::labels::side, &side);
  mesh::FacetRange(dm, &fStart, &fEnd);
  double area = 0.0;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscReal a, c[3], normal[3];
    PetscInt on_crack, s;
    DMPlexComputeCellGeometryFVM(dm, f, &a, c, normal);
    DMLabelGetValue(crack, f, &on_crack);
    DMLabelGetValue(side, f, &s);
    if (on_crack == 1) {
      area += a;
      EXPECT_NEAR((c[0] - 0.01) * n[0] + (c[1] - 0.01) * n[1], 0.0, 1e-12) << "face " << f << " off the plane";
      EXPECT_NEAR(std::abs(normal[0] * n[0] + normal[1] * n[1] + normal[2] * n[2]), 1.0, 1e-12);
    }
    if (s < 0) continue;
    const int axis[6] = {1, 0, 1, 0, 2, 2};
    const bool upper[6] = {false, true, true, false, true, false};
    EXPECT_NEAR(c[axis[s]], upper[s] ? size[axis[s]] : 0.0, 1e-12) << "outer face " << f << " side " << s;
  }
  EXPECT_NEAR(area, 0.006 * 0.004, 1e-15);
  for (const char* kind : {"source", "free", "roller", "absorbing"}) {
    PetscInt count = 0;
    DMGetStratumSize(dm, kind, 1, &count);
    EXPECT_GT(count, 0) << kind;
  }
  DM split;
  ASSERT_EQ(mesh::SplitCracks(dm, &split), 0);  // checks one cohesive cell per crack face
  DMDestroy(&split);
  DMDestroy(&dm);
}

INSTANTIATE_TEST_SUITE_P(Angles, BoxSpecimen, ::testing::Values(20.0, 70.0));

TEST(CrackFaceSubdivisions, NestTheHeatGridLines) {
  // Heat line j of n_h lies at j/n_h of the crack, sub-square edge i of m n_w at i/(m n_w):
  // every heat line is an edge iff n_h divides m n_w.
  for (int n_w = 1; n_w <= 24; ++n_w)
    for (int n_h = n_w; n_h <= 8 * n_w; ++n_h) {
      bool exact;
      const int m = mesh::CrackFaceSubdivisions({n_w, 20}, {n_h, 40}, &exact);
      ASSERT_GE(m, 4);
      ASSERT_LE(m, 16);
      const bool nests = (m * n_w) % n_h == 0 && (m * 20) % 40 == 0;
      ASSERT_EQ(exact, nests) << n_w << " wave cells, " << n_h << " heat cells: " << m << " sub-squares";
    }
  bool exact;
  EXPECT_EQ(mesh::CrackFaceSubdivisions({20, 10}, {40, 20}, &exact), 4);  // the default heat grid: halves
  EXPECT_TRUE(exact);
  EXPECT_EQ(mesh::CrackFaceSubdivisions({20, 1}, {160, 8}, &exact), 8);  // eighths (the slab of the 2D = 3D check)
  EXPECT_TRUE(exact);
  EXPECT_EQ(mesh::CrackFaceSubdivisions({20, 10}, {30, 10}, &exact), 6);  // thirds on one side
  EXPECT_TRUE(exact);
  mesh::CrackFaceSubdivisions({20, 10}, {33, 10}, &exact);  // 33 sub-squares would be needed
  EXPECT_FALSE(exact);
}

/// Crack faces of a grid and their total area.
void CrackFaces(const mesh::SpecimenGeometry& g, const mesh::BoxGrid& grid, PetscInt* count, double* area, DM* dm) {
  ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, grid, dm, count), 0);
  DMLabel crack;
  DMGetLabel(*dm, mesh::labels::crack, &crack);
  PetscInt fStart, fEnd;
  mesh::FacetRange(*dm, &fStart, &fEnd);
  *area = 0.0;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt on_crack;
    PetscReal a, c[3];
    DMLabelGetValue(crack, f, &on_crack);
    DMPlexComputeCellGeometryFVM(*dm, f, &a, c, nullptr);
    if (on_crack == 1) *area += a;
  }
}

TEST(EllipticalCrack, IsTheStaircaseOfWaveFacesInTheEllipse) {
  mesh::SpecimenGeometry g = Block(20.0);
  g.h_crack = 0.0005;
  g.cracks[0].length = 0.008, g.cracks[0].width = 0.006, g.cracks[0].shape = mesh::CrackShape::Ellipse;
  const int n1 = 16, n2 = 12;  // wave faces along the strike and z
  int expected = 0;
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n2; ++j) {
      const double u = 2.0 * (i + 0.5) / n1 - 1.0, v = 2.0 * (j + 0.5) / n2 - 1.0;
      expected += u * u + v * v <= 1.0;
    }
  const mesh::BoxGrid grid(g);
  DM dm;
  PetscInt faces;
  double area;
  CrackFaces(g, grid, &faces, &area, &dm);
  EXPECT_EQ(faces, expected);
  EXPECT_NEAR(area, expected * (0.008 / n1) * (0.006 / n2), 1e-15);
  EXPECT_NEAR(area / (0.25 * M_PI * 0.008 * 0.006), 1.0, 0.03);
  EXPECT_NEAR(grid.crack_area(), area, 1e-15);  // what the run prints
  DM split;
  ASSERT_EQ(mesh::SplitCracks(dm, &split), 0);  // checks one cohesive cell per crack face
  DMDestroy(&split);
  DMDestroy(&dm);
  const mesh::BoxGrid heat(g, mesh::BoxGridSizes{0.5 * g.h_crack, g.h, g.grading, 1e-5, 1.5});
  double heat_area;
  CrackFaces(g, heat, &faces, &heat_area, &dm);
  EXPECT_EQ(faces, 4 * expected);
  EXPECT_NEAR(heat_area, area, 1e-15);
  DMDestroy(&dm);
}

TEST(EllipticalCrack, DistanceIsToTheEllipticalDisc) {
  mesh::Crack c;
  c.x = 0.01, c.y = 0.01, c.z = 0.005, c.length = 0.008, c.width = 0.004, c.angle_deg = 30.0;
  c.shape = mesh::CrackShape::Ellipse;
  const double t = M_PI / 6, s[3] = {std::cos(t), std::sin(t), 0.0}, n[3] = {-std::sin(t), std::cos(t), 0.0};
  const auto at = [&](double along, double dz, double off) {
    return std::array<double, 3>{c.x + along * s[0] + off * n[0], c.y + along * s[1] + off * n[1], c.z + dz};
  };
  EXPECT_NEAR(c.distance_to(at(0.001, 0.001, 0.0007)), 0.0007, 1e-15);  // over the disc
  EXPECT_NEAR(c.distance_to(at(0.006, 0.0, 0.0)), 0.002, 1e-12);       // beyond the tip on the strike
  EXPECT_NEAR(c.distance_to(at(0.0, 0.005, 0.0)), 0.003, 1e-12);       // beyond the edge along z
  for (const auto& p : {at(0.004, 0.002, 0.001), at(-0.003, -0.003, -0.002), at(0.0045, -0.0001, 0.0)}) {
    double nearest = INFINITY;  // brute force over the boundary, then the disc's interior cannot be nearer
    for (int k = 0; k < 200000; ++k) {
      const double phi = 2 * M_PI * k / 200000.0;
      const auto q = at(0.004 * std::cos(phi), 0.002 * std::sin(phi), 0.0);
      nearest = std::min(nearest, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
    }
    EXPECT_NEAR(c.distance_to(p), nearest, 1e-9);
  }
  c.shape = mesh::CrackShape::Rectangle;
  EXPECT_NEAR(c.distance_to(at(0.005, 0.003, 0.0)), std::hypot(0.001, 0.001), 1e-12);
}

TEST(BoxSpecimenInput, BadGeometryNamesTheOption) {
  const auto message = [](mesh::SpecimenGeometry g) -> std::string {
    try {
      mesh::BoxGrid grid(g);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  mesh::SpecimenGeometry g = Block(20.0);
  g.cracks[0].z = 0.0085;  // reaches z = 0.0105 > depth
  EXPECT_NE(message(g).find("-crack_width"), std::string::npos) << message(g);
  g = Block(20.0);
  g.cracks[0].width = 0.0012;  // one cell of -mesh_h_crack
  EXPECT_NE(message(g).find("-crack_width"), std::string::npos) << message(g);
  g = Block(20.0);
  g.cracks.push_back(g.cracks[0]);
  EXPECT_NE(message(g).find("one crack"), std::string::npos) << message(g);
  g = Block(60.0);
  g.cracks[0].y = 0.004;
  EXPECT_NE(message(g).find("-crack_angle"), std::string::npos) << message(g);
  g = Block(20.0);
  g.cracks[0].width = g.depth, g.cracks[0].shape = mesh::CrackShape::Ellipse;  // through the thickness
  EXPECT_NE(message(g).find("-crack_shape"), std::string::npos) << message(g);
}

}  // namespace
}  // namespace vibrotherm::testing

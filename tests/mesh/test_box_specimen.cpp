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
// Several cracks (issue 26, deliverable 1): each on its own label (1, 2, ...) with its
// faces (-crack_length and -crack_width over -mesh_h_crack) in its plane, cracks on one
// line or one plane at other depths sharing a grid plane, one cohesive cell per face
// after the split; crack ends closer than a third of a cell share a grid line.
// A tilted crack (-crack_tilt δ: the plane turned about its strike, issue 26's "any
// orientation"): with θ = 0 its faces are exactly the L × W rectangle on the tilted plane
// (area, area centroid = its centre, every face on the plane whose normal is computed
// here from θ and δ); turned as well (θ = 30°, δ = 20°) it is the staircase of the faces
// whose centroids lie in its rectangle (decided here from each face's 3D centroid and the
// crack's axes computed independently), the heat grid's halves tile the same staircase, and
// one cohesive cell is added per face.
// Bad geometry is refused naming the option.
#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

/// Per crack label value (1, 2, ...): the faces, their area, and the largest distance
/// of a face centre from that crack's plane (its centre, angle).
struct LabelledCrack {
  PetscInt faces = 0;
  double area = 0.0, off_plane = 0.0;
  std::array<double, 3> centroid{};  ///< Σ area × face centroid
};

/// The crack plane's unit normal from θ and δ (written out here, not Crack::axes): the
/// in-plane normal (−sin θ, cos θ, 0) turned about the strike toward +z by δ.
std::array<double, 3> Normal(const mesh::Crack& c) {
  const double t = c.angle_deg * M_PI / 180.0, d = c.tilt_deg * M_PI / 180.0;
  return {-std::sin(t) * std::cos(d), std::cos(t) * std::cos(d), std::sin(d)};
}
std::vector<LabelledCrack> LabelledCracks(DM dm, const mesh::SpecimenGeometry& g) {
  std::vector<LabelledCrack> out(g.cracks.size());
  DMLabel crack;
  DMGetLabel(dm, mesh::labels::crack, &crack);
  PetscInt fStart, fEnd;
  mesh::FacetRange(dm, &fStart, &fEnd);
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt k;
    PetscReal a, c[3];
    DMLabelGetValue(crack, f, &k);
    if (k < 1) continue;
    DMPlexComputeCellGeometryFVM(dm, f, &a, c, nullptr);
    const mesh::Crack& cr = g.cracks.at(static_cast<std::size_t>(k - 1));
    const auto n = Normal(cr);
    LabelledCrack& l = out[static_cast<std::size_t>(k - 1)];
    ++l.faces, l.area += a;
    for (int d = 0; d < 3; ++d) l.centroid[d] += a * c[d];
    l.off_plane = std::max(l.off_plane, std::abs((c[0] - cr.x) * n[0] + (c[1] - cr.y) * n[1] + (c[2] - cr.z) * n[2]));
  }
  return out;
}

TEST(SeveralCracks, EachOnItsPlaneWithItsOwnLabelAndSplit) {
  // Two inclined cracks on parallel planes, a third collinear with the first, and a
  // fourth on the second's plane at another depth (z): four labels, three grid planes.
  mesh::SpecimenGeometry g = Block(10.0);
  g.width = 0.03, g.height = 0.024;
  mesh::Crack c = g.cracks[0];
  c.x = 0.008, c.y = 0.008, c.length = 0.004;
  mesh::Crack collinear = c;  // on the line through c at 10°
  collinear.x = 0.021, collinear.y = c.y + 0.013 * std::tan(10.0 * M_PI / 180.0);
  mesh::Crack upper = c, stacked = c;
  upper.x = 0.015, upper.y = 0.016, upper.length = 0.006, upper.width = 0.003, upper.z = 0.0025;
  stacked.x = 0.015, stacked.y = 0.016, stacked.width = 0.002, stacked.z = 0.0075;
  g.cracks = {c, upper, collinear, stacked};
  const mesh::BoxGrid grid(g);
  EXPECT_EQ(grid.crack_count(), 4);
  DM dm;
  PetscInt total;
  ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, grid, &dm, &total), 0);
  const std::vector<LabelledCrack> labelled = LabelledCracks(dm, g);
  for (std::size_t k = 0; k < g.cracks.size(); ++k) {
    const mesh::Crack& ck = g.cracks[k];
    const int n1 = static_cast<int>(std::lround(ck.length / g.h_crack)), n2 = static_cast<int>(std::lround(ck.width / g.h_crack));
    // Overlapping extents along z (cracks 2, 4 with 1, 3) add grid lines: at least n1 × n2 faces.
    EXPECT_GE(labelled[k].faces, n1 * n2) << "crack " << k + 1;
    EXPECT_EQ(labelled[k].faces, grid.crack_faces(static_cast<int>(k))) << "crack " << k + 1;
    EXPECT_NEAR(labelled[k].area, ck.length * ck.width, 1e-12 * ck.length * ck.width) << "crack " << k + 1;
    EXPECT_LT(labelled[k].off_plane, 1e-12) << "crack " << k + 1 << " off its plane";
    EXPECT_NEAR(grid.crack_area(static_cast<int>(k)), labelled[k].area, 1e-15);
  }
  EXPECT_EQ(total, labelled[0].faces + labelled[1].faces + labelled[2].faces + labelled[3].faces);
  DM split;
  ASSERT_EQ(mesh::SplitCracks(dm, &split), 0);  // checks one cohesive cell per crack face (each front labelled)
  PetscInt cStart, cEnd, cohesive = 0;
  DMPlexGetHeightStratum(split, 0, &cStart, &cEnd);
  for (PetscInt cell = cStart; cell < cEnd; ++cell) {
    bool is;
    mesh::IsCohesiveCell(split, cell, &is);
    cohesive += is;
  }
  EXPECT_EQ(cohesive, total);
  DMDestroy(&split);
  DMDestroy(&dm);
}

TEST(SeveralCracks, EachHasItsOwnShape) {
  // An ellipse and a rectangle on parallel planes (-crack_shape ellipse,rectangle): the
  // first is its staircase (counted as in EllipticalCrack), the second its whole rectangle.
  mesh::SpecimenGeometry g = Block(0.0);
  mesh::Crack ellipse = g.cracks[0], rectangle = g.cracks[0];
  ellipse.y = 0.007, ellipse.shape = mesh::CrackShape::Ellipse;
  rectangle.y = 0.013;
  g.cracks = {ellipse, rectangle};
  const mesh::BoxGrid grid(g);
  int expected = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 4; ++j) {
      const double u = 2.0 * (i + 0.5) / 6 - 1.0, v = 2.0 * (j + 0.5) / 4 - 1.0;
      expected += u * u + v * v <= 1.0;
    }
  EXPECT_EQ(grid.crack_faces(0), expected);
  EXPECT_EQ(grid.crack_faces(1), 6 * 4);
  EXPECT_NEAR(grid.crack_area(1), 0.006 * 0.004, 1e-15);
}

TEST(SeveralCracks, EnEchelonCracksSideBySide) {
  // Two parallel 6 x 4 mm cracks at 10° or 15°, side by side on two planes (centres 16 mm
  // apart along x, the second level with the first or 2 mm lower: 2.8-6.3 mm apart along y).
  // A shear clamped to each plane's own cracks put the second plane's surface under the first
  // at the first crack's x and refused them as folding; clamped to one window for both, they
  // are what the run needs: exact rectangles on their planes, one cohesive cell a face.
  for (const auto& [angle, rise] : {std::pair{10.0, 0.0}, std::pair{10.0, -0.002}, std::pair{15.0, 0.0},
                                    std::pair{15.0, -0.002}}) {
    mesh::SpecimenGeometry g = Block(angle);
    g.width = 0.04, g.height = 0.04, g.depth = 0.02;
    mesh::Crack a = g.cracks[0];
    a.length = 0.006, a.width = 0.004, a.x = 0.012, a.y = 0.02, a.z = 0.01;
    mesh::Crack b = a;
    b.x = 0.028, b.y = 0.02 + rise;
    g.cracks = {a, b};
    std::unique_ptr<mesh::BoxGrid> grid;
    ASSERT_NO_THROW(grid = std::make_unique<mesh::BoxGrid>(g)) << angle << " degrees, second crack " << rise << " m higher";
    DM dm;
    PetscInt total;
    ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, *grid, &dm, &total), 0);
    const std::vector<LabelledCrack> labelled = LabelledCracks(dm, g);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(labelled[k].area, 0.006 * 0.004, 1e-12 * 0.006 * 0.004) << "crack " << k + 1 << ", rise " << rise;
      EXPECT_LT(labelled[k].off_plane, 1e-12) << "crack " << k + 1 << " off its plane, rise " << rise;
    }
    DM split;
    ASSERT_EQ(mesh::SplitCracks(dm, &split), 0);  // one cohesive cell per crack face
    DMDestroy(&split);
    DMDestroy(&dm);
  }
}

TEST(SeveralCracks, NearbyEndsShareAGridLineInsteadOfASliver) {
  // Equal lengths at 5° and 6°: their ends along x are 5 µm apart, which would be a
  // cell of 5 µm (a 200 times smaller stable step). They share one line instead.
  mesh::SpecimenGeometry g = Block(0.0);
  mesh::Crack a = g.cracks[0], b = g.cracks[0];
  a.y = 0.007, a.angle_deg = -5.0, b.y = 0.013, b.angle_deg = 6.0;
  g.cracks = {a, b};
  const mesh::BoxGrid grid(g);
  EXPECT_GT(grid.h_min(), 0.5 * g.h_crack);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(grid.crack_area(k), 0.006 * 0.004, 0.002 * 0.006 * 0.004) << k;
}

TEST(SeveralCracks, SnapChainsAndFacesStay) {
  // Ends 0.3 mm apart in a chain (a, a + 0.3, a + 0.6 with snap h/3 = 0.333 mm): the chain
  // joins its smallest end, no cell thinner than the snap distance is left.
  const mesh::BoxGridSizes sizes{0.001, 0.002, 0.5};
  std::vector<mesh::AxisSegment> chain = {{0.005, 0.011, 6}, {0.0053, 0.0113, 6}, {0.0056, 0.0116, 6}};
  mesh::SnapEnds(&chain, 0.001 / 3.0, 0.02);
  const std::vector<double> x = mesh::AxisNodes(0.02, chain, sizes);
  double thinnest = INFINITY;
  for (std::size_t i = 1; i < x.size(); ++i) thinnest = std::min(thinnest, x[i] - x[i - 1]);
  EXPECT_GT(thinnest, 0.001 / 3.0);
  // An end 0.2 mm from the face stays there (snapping it would make the crack reach the face).
  std::vector<mesh::AxisSegment> near_face = {{0.0, 0.01, 10}, {0.0002, 0.004, 4}};
  mesh::SnapEnds(&near_face, 0.001 / 3.0, 0.01);
  const std::vector<double> z = mesh::AxisNodes(0.01, near_face, sizes);
  EXPECT_NE(std::find_if(z.begin(), z.end(), [](double v) { return std::abs(v - 0.0002) < 1e-12; }), z.end());
}

TEST(SeveralCracks, FaceSubdivisionsFollowUnevenCells) {
  // Extents overlapping along x on two planes (7-13 and 9.5-15.5 mm) make uneven wave cells
  // (0.833 and 0.875 mm); the heat grid halves each of them (refine 2), so 4 sub-squares
  // nest it exactly.
  mesh::SpecimenGeometry g = Block(0.0);
  mesh::Crack a = g.cracks[0], b = g.cracks[0];
  a.x = 0.010, a.y = 0.007, b.x = 0.0125, b.y = 0.013;
  g.cracks = {a, b};
  const mesh::BoxGridSizes halves{0.0005, g.h, g.grading, 1e-5, 1.5};
  const mesh::BoxGrid wave(g), heat(g, halves);
  bool exact = false;
  EXPECT_EQ(mesh::CrackFaceSubdivisions(wave, heat, &exact), 4);
  EXPECT_TRUE(exact);
  // A transducer patch bound over a rectangular crack (x = 9.3 mm) moves the nearest wave
  // line (9 mm) in both grids, the heat grid's lines between stretched with it: still halves.
  // (Moving each grid's own nearest line, 9 mm and 9.5 mm, nested in no m <= 16, and the
  // cell totals alone would not tell.)
  g.cracks = {a};
  g.edges[static_cast<int>(mesh::Side::Top)] = mesh::EdgeKind::Free;
  g.patch = {true, mesh::Side::Top, 0.0113, 0.004, 0.005, 0.01};
  const mesh::BoxGrid wave1(g), heat1(g, halves);
  EXPECT_EQ(mesh::CrackFaceSubdivisions(wave1, heat1, &exact), 4);
  EXPECT_TRUE(exact);
  EXPECT_EQ(heat1.crack_cells(0), 2 * wave1.crack_cells(0));
  // options/block3d.opts: its patch's x bounds (15, 25 mm) both fall inside the 20° crack's range.
  mesh::SpecimenGeometry b3 = Block(20.0);
  b3.width = 0.04, b3.height = 0.04, b3.depth = 0.02, b3.h = 0.002, b3.h_crack = 0.001;
  b3.cracks[0].x = 0.02, b3.cracks[0].y = 0.02, b3.cracks[0].z = 0.01;
  b3.cracks[0].length = 0.02, b3.cracks[0].width = 0.01;
  b3.edges[static_cast<int>(mesh::Side::Top)] = mesh::EdgeKind::Free;
  b3.patch = {true, mesh::Side::Top, 0.02, 0.01, 0.01, 0.01};
  const mesh::BoxGrid wave3(b3), heat3(b3, mesh::BoxGridSizes{0.0005, b3.h, b3.grading, 1e-5, 1.5});
  EXPECT_EQ(mesh::CrackFaceSubdivisions(wave3, heat3, &exact), 4);
  EXPECT_TRUE(exact);
}

TEST(TiltedCrack, UnturnedIsTheExactRectangleOnItsPlane) {
  for (double tilt : {25.0, -25.0, 90.0}) {  // 90: parallel to the front face, grid planes normal to z
    mesh::SpecimenGeometry g = Block(0.0);
    g.cracks[0].tilt_deg = tilt;
    const mesh::BoxGrid grid(g);
    DM dm;
    PetscInt total;
    ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, grid, &dm, &total), 0);
    const LabelledCrack l = LabelledCracks(dm, g)[0];
    EXPECT_EQ(l.faces, 6 * 4) << tilt;  // 6 mm x 4 mm in cells of 1 mm along the strike and the up-dip
    EXPECT_NEAR(l.area, 0.006 * 0.004, 1e-12 * 0.006 * 0.004) << tilt;
    EXPECT_LT(l.off_plane, 1e-12) << tilt;
    const mesh::Crack& c = g.cracks[0];
    const double centre[3] = {c.x, c.y, c.z};
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(l.centroid[d] / l.area, centre[d], 1e-12) << tilt << " axis " << d;
    DM split;
    ASSERT_EQ(mesh::SplitCracks(dm, &split), 0);  // one cohesive cell per crack face
    DMDestroy(&split);
    DMDestroy(&dm);
  }
}

/// The faces of dm on crack c's plane whose centroids lie in its L × W rectangle, counted
/// from their 3D centroids and the crack's strike and up-dip written out here; and whether
/// every such face, and no other, carries the crack label.
void StaircaseOf(DM dm, const mesh::Crack& c, PetscInt* faces, bool* labels_agree, PetscInt label = 1) {
  const double t = c.angle_deg * M_PI / 180.0, d = c.tilt_deg * M_PI / 180.0;
  const double s[3] = {std::cos(t), std::sin(t), 0.0};
  const double w[3] = {std::sin(d) * std::sin(t), -std::sin(d) * std::cos(t), std::cos(d)};
  const auto n = Normal(c);
  DMLabel crack;
  DMGetLabel(dm, mesh::labels::crack, &crack);
  PetscInt fStart, fEnd;
  mesh::FacetRange(dm, &fStart, &fEnd);
  *faces = 0, *labels_agree = true;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscReal a, x[3];
    PetscInt k;
    DMPlexComputeCellGeometryFVM(dm, f, &a, x, nullptr);
    DMLabelGetValue(crack, f, &k);
    const double r[3] = {x[0] - c.x, x[1] - c.y, x[2] - c.z};
    const auto dot = [&r](const auto& u) { return r[0] * u[0] + r[1] * u[1] + r[2] * u[2]; };
    const bool in = std::abs(dot(n)) < 1e-9 && std::abs(dot(s)) <= 0.5 * c.length && std::abs(dot(w)) <= 0.5 * c.width;
    *faces += in;
    if (in != (k == label)) *labels_agree = false;
  }
}

TEST(TiltedCrack, TurnedIsTheStaircaseOfItsRectangle) {
  mesh::SpecimenGeometry g = Block(30.0);
  g.width = 0.04, g.height = 0.04, g.depth = 0.02, g.h_crack = 0.0005;
  g.cracks[0].x = 0.02, g.cracks[0].y = 0.02, g.cracks[0].z = 0.01;
  g.cracks[0].length = 0.008, g.cracks[0].width = 0.006, g.cracks[0].tilt_deg = 20.0;
  const mesh::BoxGrid grid(g);
  DM dm;
  PetscInt total, expected;
  bool agree;
  ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, grid, &dm, &total), 0);
  StaircaseOf(dm, g.cracks[0], &expected, &agree);
  EXPECT_TRUE(agree) << "labelled faces differ from those in the rectangle";
  EXPECT_EQ(total, expected);
  EXPECT_LT(total, grid.crack_cells(0) * grid.crack_cells(1));  // a staircase, not the bounding rectangle
  const LabelledCrack l = LabelledCracks(dm, g)[0];
  EXPECT_LT(l.off_plane, 1e-12);
  EXPECT_NEAR(l.area / (0.008 * 0.006), 1.0, 0.03);
  EXPECT_NEAR(grid.crack_area(), l.area, 1e-15);
  DM split;
  ASSERT_EQ(mesh::SplitCracks(dm, &split), 0);
  DMDestroy(&split);
  DMDestroy(&dm);
  const mesh::BoxGrid heat(g, mesh::BoxGridSizes{0.5 * g.h_crack, g.h, g.grading, 1e-5, 1.5});
  ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, g, heat, &dm, &total), 0);
  EXPECT_EQ(total, 4 * expected);  // the heat grid's halves tile the wave staircase
  EXPECT_NEAR(LabelledCracks(dm, g)[0].area, l.area, 1e-15);
  DMDestroy(&dm);
}

TEST(TiltedCrack, StaircaseNestsBesideAnotherCrackAndUnderAPatch) {
  // Two parallel cracks at 30° tilted by 20°, 2.83 mm apart along their normal and shifted
  // 0.62 mm along x: their extents overlap, so the wave cells over each are uneven. Each
  // crack is still the staircase of the wave faces whose centroids lie in its rectangle, and
  // the heat grid halves every wave face (4 heat faces each, the same area).
  mesh::SpecimenGeometry g = Block(30.0);
  g.width = 0.04, g.height = 0.04, g.depth = 0.04, g.h_crack = 0.0005;
  mesh::Crack a = g.cracks[0];
  a.x = 0.02, a.y = 0.02, a.z = 0.02, a.length = 0.008, a.width = 0.006, a.tilt_deg = 20.0;
  mesh::Crack b = a;
  b.x = 0.02062, b.y = 0.023256, b.z = 0.021368;
  g.cracks = {a, b};
  const auto check = [&](const mesh::SpecimenGeometry& geometry, const char* what) {
    const mesh::BoxGrid wave(geometry), heat(geometry, mesh::BoxGridSizes{0.5 * g.h_crack, g.h, g.grading, 1e-5, 1.5});
    DM dm, heat_dm;
    PetscInt total, heat_total;
    ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, geometry, wave, &dm, &total), 0);
    ASSERT_EQ(mesh::CreateBoxPlex(PETSC_COMM_SELF, geometry, heat, &heat_dm, &heat_total), 0);
    const std::vector<LabelledCrack> w = LabelledCracks(dm, geometry), h = LabelledCracks(heat_dm, geometry);
    for (std::size_t k = 0; k < geometry.cracks.size(); ++k) {
      PetscInt expected;
      bool agree;
      StaircaseOf(dm, geometry.cracks[k], &expected, &agree, static_cast<PetscInt>(k + 1));
      EXPECT_TRUE(agree) << what << ": crack " << k + 1 << "'s labelled faces differ from those in its rectangle";
      EXPECT_EQ(w[k].faces, expected) << what << ": crack " << k + 1;
      EXPECT_EQ(h[k].faces, 4 * w[k].faces) << what << ": crack " << k + 1;
      EXPECT_NEAR(h[k].area, w[k].area, 1e-15) << what << ": crack " << k + 1;
    }
    DMDestroy(&dm);
    DMDestroy(&heat_dm);
  };
  check(g, "two cracks");
  // One crack under a transducer patch whose x bound (18.3 mm) falls inside its range.
  g.cracks = {a};
  g.edges[static_cast<int>(mesh::Side::Top)] = mesh::EdgeKind::Free;
  g.patch = {true, mesh::Side::Top, 0.0203, 0.004, 0.02, 0.01};
  check(g, "patch");
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
  EXPECT_NE(message(g).find("cracks 1 and 2 overlap"), std::string::npos) << message(g);
  g = Block(60.0);
  g.cracks[0].x = 0.004;  // sheared along x, 4 mm from the face x = 0
  EXPECT_NE(message(g).find("-crack_angle"), std::string::npos) << message(g);
  g = Block(0.0);
  g.cracks.push_back(g.cracks[0]);
  g.cracks[1].y += 0.0015;  // a parallel plane 1.5 cells away
  EXPECT_NE(message(g).find("crack planes"), std::string::npos) << message(g);
  g.cracks[1].y = 0.01, g.cracks[1].x += 0.0065;  // on the same line, 0.5 mm from the first
  EXPECT_NE(message(g).find("cracks 1 and 2 overlap or come closer"), std::string::npos) << message(g);
  g.cracks[1] = g.cracks[0], g.cracks[1].angle_deg = 60.0, g.cracks[1].y = 0.016;
  EXPECT_NE(message(g).find("normals nearest one axis"), std::string::npos) << message(g);
  g.cracks[1].angle_deg = -20.0, g.cracks[1].y = 0.015, g.cracks[0].angle_deg = 20.0;  // planes that meet
  EXPECT_NE(message(g).find("without folding"), std::string::npos) << message(g);
  g = Block(20.0);
  g.cracks[0].width = g.depth, g.cracks[0].shape = mesh::CrackShape::Ellipse;  // through the thickness
  EXPECT_NE(message(g).find("-crack_shape"), std::string::npos) << message(g);
  g = Block(0.0);
  g.cracks[0].tilt_deg = 95.0;
  EXPECT_NE(message(g).find("-crack_tilt must lie in"), std::string::npos) << message(g);
  g.cracks[0].tilt_deg = 45.0, g.cracks[0].y = 0.001;  // untilted it is buried; tilted it leaves through y = 0
  EXPECT_NE(message(g).find("-crack_tilt: the crack reaches the outside"), std::string::npos) << message(g);
  g = Block(0.0);
  g.cracks[0].tilt_deg = 10.0, g.cracks[0].width = g.depth;  // meant through the thickness
  EXPECT_NE(message(g).find("-crack_tilt: a crack through the thickness"), std::string::npos) << message(g);
  g = Block(0.0);  // two cracks parallel to the front face, one turned across the other
  g.cracks[0].tilt_deg = 90.0, g.cracks[0].length = 0.006, g.cracks[0].width = 0.004;
  g.cracks.push_back(g.cracks[0]);
  g.cracks[1].x = 0.015, g.cracks[1].angle_deg = 90.0, g.cracks[1].length = 0.002, g.cracks[1].width = 0.008;
  EXPECT_NE(message(g).find("cracks 1 and 2 overlap"), std::string::npos) << message(g);
  g = Block(0.0);
  g.cracks[0].tilt_deg = 40.0, g.cracks[0].y = 0.004;  // sheared along y by 3 mm, 4 mm from the face y = 0
  EXPECT_NE(message(g).find("without folding"), std::string::npos) << message(g);
}

}  // namespace
}  // namespace vibrotherm::testing

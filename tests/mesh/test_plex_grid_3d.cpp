// Requirement (issue 26, item 6: XDMF/HDF5 with 3D cells): the grid ParaView reads is
// the mesh, in 3D as in 2D. On a hex box and on Kuhn tetrahedra, each with a buried
// crack split into cohesive cells:
//  - every vertex has its three coordinates;
//  - bulk cells come in XDMF's (VTK's) corner order: a hexahedron's corners 0–3 are one
//    face in cyclic order, 4–7 the opposite face, corner i + 4 above corner i, and the
//    first face's normal (p1 − p0) × (p3 − p0) points to the second face; a tetrahedron's
//    (p1 − p0) × (p2 − p0) points to p3 (positive volume in VTK's convention);
//  - the crack grid has one quadrilateral (a triangle on tets) per crack face, its corners
//    in the crack plane and in cyclic order (consecutive corners share an edge);
//  - the .xmf says XYZ, Hexahedron/Tetrahedron and Quadrilateral/Triangle, with the
//    dimensions of the datasets.
// PETSc stores the first face of a 3D cell with its normal inward: written in closure
// order, every cell would be inside out for ParaView (the control: the same check on
// the closure order, DMPlexInvertCell undone, finds every cell inverted).
#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "crack_box_support.hpp"
#include "vibrotherm/io/field_output.hpp"
#include "vibrotherm/io/plex_grid.hpp"
#include "vibrotherm/mesh/plex/crack_split.hpp"

namespace vibrotherm::testing {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 Minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double TripleProduct(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
double Distance(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

class PlexGrid3D : public ::testing::TestWithParam<bool> {  // true: tets
 protected:
  void SetUp() override {
    ASSERT_EQ(MakeCrackBox(GetParam(), -0.5, 0.5, &box_), 0);
    ASSERT_EQ(mesh::SplitCracks(box_.dm, &split_), 0);
    ASSERT_EQ(io::OwnedVertices(split_, &vertices_), 0);
    for (std::size_t i = 0; i < vertices_.rows.size(); ++i)
      x_[vertices_.rows[i]] = {vertices_.coordinates[3 * i], vertices_.coordinates[3 * i + 1],
                               vertices_.coordinates[3 * i + 2]};
  }
  void TearDown() override { DMDestroy(&split_); }
  /// VTK's orientation: a tetrahedron's (p1 − p0) × (p2 − p0) and a hexahedron's (p1 − p0) × (p3 − p0) point to p3, p4.
  bool Inverted(const PetscInt* c, PetscInt corners) const {
    const Vec3 &p0 = x_.at(c[0]), &p1 = x_.at(c[1]), &p2 = x_.at(c[2]), &p3 = x_.at(c[3]);
    if (corners == 4) return TripleProduct(Minus(p1, p0), Minus(p2, p0), Minus(p3, p0)) <= 0;
    return TripleProduct(Minus(p1, p0), Minus(p3, p0), Minus(x_.at(c[4]), p0)) <= 0;
  }
  CrackBox box_;
  DM split_ = nullptr;
  io::PlexVertices vertices_;
  std::map<PetscInt, Vec3> x_;
};

TEST_P(PlexGrid3D, VerticesHaveThreeCoordinates) {
  EXPECT_EQ(vertices_.dim, 3);
  EXPECT_EQ(vertices_.coordinates.size(), 3 * vertices_.rows.size());
  EXPECT_EQ(static_cast<PetscInt>(vertices_.rows.size()), vertices_.global);
}

TEST_P(PlexGrid3D, BulkCellsInVtkOrder) {
  std::vector<PetscInt> cells;
  PetscInt corners;
  ASSERT_EQ(io::OwnedBulkCells(split_, &cells, &corners), 0);
  ASSERT_EQ(corners, GetParam() ? 4 : 8);
  int inverted = 0, misshapen = 0, closure_inverted = 0;
  const DMPolytopeType type = corners == 4 ? DM_POLYTOPE_TETRAHEDRON : DM_POLYTOPE_HEXAHEDRON;
  for (std::size_t c = 0; c < cells.size(); c += corners) {
    std::vector<PetscInt> closure(cells.begin() + c, cells.begin() + c + corners);
    ASSERT_EQ(DMPlexInvertCell(type, closure.data()), 0);  // back to Plex's closure order
    inverted += Inverted(cells.data() + c, corners);
    closure_inverted += Inverted(closure.data(), corners);
    if (corners == 4) continue;
    std::vector<Vec3> p;
    for (PetscInt k = 0; k < corners; ++k) p.push_back(x_.at(cells[c + k]));
    const Vec3 up = Minus(p[4], p[0]);
    for (int i = 1; i < 4; ++i) misshapen += Distance(Minus(p[i + 4], p[i]), up) > 1e-12;  // i + 4 above i
    for (int i = 0; i < 4; ++i) misshapen += std::abs(Distance(p[i], p[(i + 1) % 4]) - 0.25) > 1e-12;  // cyclic
  }
  const int count = static_cast<int>(cells.size() / corners);
  std::printf("  %s: %d cells, %d inverted (closure order: %d), %d misshapen\n", GetParam() ? "tets" : "hexes", count,
              inverted, closure_inverted, misshapen);
  EXPECT_EQ(inverted, 0);
  EXPECT_EQ(misshapen, 0);
  EXPECT_EQ(closure_inverted, count);
}

TEST_P(PlexGrid3D, CrackFacesInTheirPlaneAndCyclic) {
  std::vector<PetscInt> faces;
  PetscInt corners;
  ASSERT_EQ(io::OwnedCohesiveFaces(split_, &faces, &corners), 0);
  ASSERT_EQ(corners, GetParam() ? 3 : 4);
  EXPECT_EQ(static_cast<PetscInt>(faces.size()) / corners, box_.crack_faces);
  int off_plane = 0, diagonal = 0;
  for (std::size_t f = 0; f < faces.size(); f += corners)
    for (PetscInt k = 0; k < corners; ++k) {
      const Vec3 &a = x_.at(faces[f + k]), &b = x_.at(faces[f + (k + 1) % corners]);
      off_plane += std::abs(a[2]) > 1e-12;
      // quads: consecutive corners are one cell edge apart (0.25), never the diagonal
      diagonal += corners == 4 && std::abs(Distance(a, b) - 0.25) > 1e-12;
    }
  EXPECT_EQ(off_plane, 0);
  EXPECT_EQ(diagonal, 0);
}

TEST_P(PlexGrid3D, XdmfDescribesThreeDimensions) {
  const std::string dir = (std::filesystem::temp_directory_path() / ("vt_grid3d_" + std::to_string(GetParam()))).string();
  std::filesystem::create_directories(dir);
  {
    io::FieldFile file;
    ASSERT_EQ(file.Open(PETSC_COMM_SELF, dir + "/mesh.h5", io::XdmfLayout::kStaticGrids), 0);
    ASSERT_EQ(file.AddMesh("wave", split_), 0);
    ASSERT_EQ(file.AddCohesiveCells("cracks", "wave"), 0);
    ASSERT_EQ(file.Finish(), 0);
  }
  std::ifstream in(dir + "/mesh.xmf");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xmf = text.str();
  const std::string bulk = GetParam() ? "Tetrahedron" : "Hexahedron", crack = GetParam() ? "Triangle" : "Quadrilateral";
  EXPECT_NE(xmf.find("GeometryType=\"XYZ\""), std::string::npos) << xmf;
  EXPECT_NE(xmf.find("TopologyType=\"" + bulk + "\""), std::string::npos) << xmf;
  EXPECT_NE(xmf.find("TopologyType=\"" + crack + "\""), std::string::npos) << xmf;
  EXPECT_NE(xmf.find("Dimensions=\"" + std::to_string(vertices_.global) + " 3\""), std::string::npos) << xmf;
  if (!std::getenv("VIBROTHERM_KEEP_GRID3D")) std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Boxes, PlexGrid3D, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "tets" : "hexes"; });

}  // namespace
}  // namespace vibrotherm::testing

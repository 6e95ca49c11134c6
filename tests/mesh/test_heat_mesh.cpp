// Requirement: the heat mesh of a generated specimen is graded to every crack —
// all quads; its crack facets cover each crack exactly, none longer than
// -heat_mesh_h_along; the cells on the crack are one first layer thick
// (-heat_mesh_h_crack; up to (1 + growth)/2 of it where the full-quad fallback split layers);
// crack facets are numbered from the crack end with the smaller x; buried tips
// and ends on the outer edge both work; DMPlex consistency checks pass; the mesh
// is partitioned on its own (both ranks hold cells). Serial and 2 ranks.
#include <cmath>
#include <algorithm>
#include <map>
#include <set>

#include "mesh_test_support.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::testing {
namespace {

struct Scene {
  const char* name;
  std::string options;
  std::vector<mesh::Crack> cracks;
};

constexpr double kFirstLayer = 5e-6, kAlong = 4e-4, kGrowth = 1.3;

std::vector<Scene> Scenes() {
  const std::string box = "-specimen_width 0.05 -specimen_height 0.1 -mesh_h 0.004 -mesh_h_crack 0.001 "
                          "-heat_mesh_h_crack 5e-6 -heat_mesh_h_along 4e-4 -heat_mesh_growth 1.3 ";
  const mesh::Crack a{0.015, 0.025, 0.01, 0}, b{0.03, 0.05, 0.015, 45}, c{0.02, 0.08, 0.012, 150};
  return {
      {"three buried cracks", box + "-crack_center 0.015,0.025,0.03,0.05,0.02,0.08 -crack_length 0.01,0.015,0.012 "
                                    "-crack_angle 0,45,150",
       {a, b, c}},
      {"interface across the width", box + "-crack_center 0.025,0.05 -crack_length 0.05 -crack_angle 0",
       {{0.025, 0.05, 0.05, 0}}},
      {"inclined edge crack", box + "-crack_center 0.008660254037844386,0.05 -crack_length 0.02 -crack_angle 30",
       {{0.008660254037844386, 0.05, 0.02, 30}}},
  };
}

/// Distance from p to the line through a and b (the layers are parallel to it).
double DistanceToLine(const std::array<double, 2>& p, const std::array<double, 2>& a, const std::array<double, 2>& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  return std::abs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / std::hypot(dx, dy);
}

class HeatMesh : public ::testing::TestWithParam<int> {};

TEST_P(HeatMesh, IsGradedToEveryCrack) {
  const Scene scene = Scenes()[GetParam()];
  ScopedSpecimen s(scene.options);
  ASSERT_EQ(s.status, 0) << scene.name;
  DM dm = s.specimen.heat;
  EXPECT_EQ(DMPlexCheckSymmetry(dm), 0);
  EXPECT_EQ(DMPlexCheckGeometry(dm), 0);
  EXPECT_EQ(s.summary.heat_source, "graded");
  for (PetscInt n : s.summary.heat_cells_per_rank) EXPECT_GT(n, 0) << "a rank without heat cells";
  mesh::VertexCoordinates x;
  ASSERT_EQ(x.Setup(dm), 0);
  DMLabel crack_label;
  ASSERT_EQ(DMGetLabel(dm, mesh::labels::crack, &crack_label), 0);
  PetscInt cStart, cEnd, fStart, fEnd;
  DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd);
  DMPlexGetDepthStratum(dm, 1, &fStart, &fEnd);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt n;
    DMPlexGetConeSize(dm, c, &n);
    ASSERT_EQ(n, 4) << "cell " << c << " is not a quadrilateral";
  }
  // Thickness of the cells on the crack: the farthest of their vertices from the crack's line.
  double thinnest = INFINITY, thickest = 0.0;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt id;
    DMLabelGetValue(crack_label, f, &id);
    if (id < 1) continue;
    const mesh::Crack& k = scene.cracks.at(id - 1);
    const PetscInt* support;
    PetscInt ns;
    DMPlexGetSupportSize(dm, f, &ns);
    DMPlexGetSupport(dm, f, &support);
    for (PetscInt j = 0; j < ns; ++j) {
      std::set<PetscInt> verts;
      PetscInt* closure = nullptr;
      PetscInt n, vStart, vEnd;
      DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd);
      DMPlexGetTransitiveClosure(dm, support[j], PETSC_TRUE, &n, &closure);
      double far = 0.0;
      for (PetscInt i = 0; i < 2 * n; i += 2)
        if (closure[i] >= vStart && closure[i] < vEnd)
          far = std::max(far, DistanceToLine(x(closure[i]), k.end(0), k.end(1)));
      DMPlexRestoreTransitiveClosure(dm, support[j], PETSC_TRUE, &n, &closure);
      thinnest = std::min(thinnest, far);
      thickest = std::max(thickest, far);
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, &thinnest, 1, MPI_DOUBLE, MPI_MIN, PETSC_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &thickest, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  EXPECT_GE(thinnest, 0.99 * kFirstLayer) << scene.name;
  EXPECT_LE(thickest, 1.05 * kFirstLayer * (1 + kGrowth) / 2) << scene.name;
  for (std::size_t i = 0; i < scene.cracks.size(); ++i) {
    const mesh::CrackLine& line = s.specimen.heat_cracks.line(static_cast<PetscInt>(i));
    EXPECT_NEAR(line.length(), scene.cracks[i].length, 1e-9 * scene.cracks[i].length) << "crack " << i + 1;
    const auto e0 = scene.cracks[i].end(0), e1 = scene.cracks[i].end(1);
    const auto first = e0[0] < e1[0] ? e0 : e1;
    EXPECT_LT(std::hypot(line.vertex(0)[0] - first[0], line.vertex(0)[1] - first[1]), 1e-9) << "ξ = 0 end";
    for (std::size_t k = 0; k + 1 <= line.facet_ids().size(); ++k) {
      const double l = std::hypot(line.vertex(k + 1)[0] - line.vertex(k)[0], line.vertex(k + 1)[1] - line.vertex(k)[1]);
      EXPECT_LE(l, kAlong * (1 + 1e-9)) << "crack " << i + 1 << " facet " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, HeatMesh, ::testing::Range(0, static_cast<int>(Scenes().size())));

}  // namespace
}  // namespace vibrotherm::testing

// Requirement: splitting is geometrically right on the paper scene, on three
// cracks (quads and triangles) and on cracks that reach the outer edges:
// cohesive cells = crack facets; tips not duplicated; every other crack vertex
// duplicated exactly once; the two bulk cells of each cohesive cell on opposite
// sides of the crack line and really separated; crack length exact; DMPlex
// consistency checks pass. Runs serial and on 2 ranks.
#include <cmath>
#include <map>
#include <set>

#include "mesh_test_support.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::testing {
namespace {

struct Scene {
  const char* name;
  std::string options;
  std::vector<mesh::Crack> cracks;
};

const std::string kSource = VIBROTHERM_SOURCE_DIR;

mesh::Crack crack(double x, double y, double L, double deg) { return {x, y, L, deg}; }

std::vector<Scene> Scenes() {
  const std::string box = "-specimen_width 0.05 -specimen_height 0.1 -mesh_h 0.004 -mesh_h_crack 0.001 ";
  const std::string three = "-crack_center 0.015,0.025,0.03,0.05,0.02,0.08 -crack_length 0.01,0.015,0.012 "
                            "-crack_angle 0,45,-30 ";
  const std::vector<mesh::Crack> three_cracks = {crack(0.015, 0.025, 0.01, 0), crack(0.03, 0.05, 0.015, 45),
                                                 crack(0.02, 0.08, 0.012, -30)};
  return {
      {"paper", "-options_file " + kSource + "/options/paper.opts", {crack(0.025, 0.05, 0.02, 20)}},
      {"three cracks, quads", box + three, three_cracks},
      {"three cracks, triangles", box + three + "-mesh_cell tri", three_cracks},
      {"interface across the width", box + "-crack_center 0.025,0.05 -crack_length 0.05 -crack_angle 0",
       {crack(0.025, 0.05, 0.05, 0)}},
      {"edge crack from the left edge", box + "-crack_center 0.01,0.05 -crack_length 0.02 -crack_angle 0",
       {crack(0.01, 0.05, 0.02, 0)}},
      {"refined twice", box + "-crack_center 0.025,0.05 -crack_length 0.02 -crack_angle 20 -dm_refine 2",
       {crack(0.025, 0.05, 0.02, 20)}},
  };
}

std::array<double, 2> Centroid(DM dm, const mesh::VertexCoordinates& x, PetscInt cell, std::set<PetscInt>* verts) {
  PetscInt* closure = nullptr;
  PetscInt n, vStart, vEnd;
  std::array<double, 2> c = {0, 0};
  (void)DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd);
  (void)DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure);
  int count = 0;
  for (PetscInt i = 0; i < 2 * n; i += 2) {
    if (closure[i] < vStart || closure[i] >= vEnd) continue;
    const auto p = x(closure[i]);
    c[0] += p[0], c[1] += p[1], ++count;
    if (verts) verts->insert(closure[i]);
  }
  (void)DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &n, &closure);
  return {c[0] / count, c[1] / count};
}

class CrackSplit : public ::testing::TestWithParam<int> {};

TEST_P(CrackSplit, IsGeometricallyCorrect) {
  const Scene scene = Scenes()[GetParam()];
  SCOPED_TRACE(scene.name);
  ScopedSpecimen s(scene.options + " -heat_mesh wave");  // the split is checked against the unsplit mesh
  ASSERT_EQ(s.status, 0);
  DM wave = s.specimen.wave, heat = s.specimen.heat;
  ASSERT_EQ(s.summary.cracks.size(), scene.cracks.size());

  // Crack facets and vertices of the unsplit mesh.
  DMLabel heat_crack, heat_tip;
  DMGetLabel(heat, mesh::labels::crack, &heat_crack);
  DMGetLabel(heat, mesh::labels::crack_tip, &heat_tip);
  std::vector<long long> facets(scene.cracks.size(), 0);
  std::vector<bool> ghost;
  mesh::GhostPoints(heat, &ghost);
  PetscInt chart0, fStart, fEnd;
  DMPlexGetChart(heat, &chart0, nullptr);
  DMPlexGetDepthStratum(heat, 1, &fStart, &fEnd);
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt id;
    DMLabelGetValue(heat_crack, f, &id);
    if (id > 0 && !ghost[f - chart0]) ++facets[id - 1];
  }
  auto on_crack = [&](PetscInt v) {
    const PetscInt* support;
    PetscInt n;
    DMPlexGetSupportSize(heat, v, &n);
    DMPlexGetSupport(heat, v, &support);
    for (PetscInt k = 0; k < n; ++k) {
      PetscInt id;
      DMLabelGetValue(heat_crack, support[k], &id);
      if (id > 0) return true;
    }
    return false;
  };
  auto is_tip = [&](PetscInt v) {
    PetscInt t;
    DMLabelGetValue(heat_tip, v, &t);
    return t == 1;
  };
  const auto crack_vertices = AllGather(OwnedVertexCoordinates(heat, [&](PetscInt v) { return on_crack(v) && !is_tip(v); }));
  const auto tips = AllGather(OwnedVertexCoordinates(heat, is_tip));
  const auto split_vertices = AllGather(OwnedVertexCoordinates(wave, [](PetscInt) { return true; }));

  for (std::size_t c = 0; c < scene.cracks.size(); ++c) {
    const mesh::CrackSummary& cs = s.summary.cracks[c];
    EXPECT_EQ(cs.facets, Sum(facets[c])) << "cohesive cells != crack facets, crack " << c + 1;
    EXPECT_NEAR(cs.length, scene.cracks[c].length, 1e-12 * scene.cracks[c].length) << "crack " << c + 1;
    EXPECT_GE(cs.facets, 2);
  }

  // Tips once, every other crack vertex twice, every other vertex once.
  std::map<std::array<double, 2>, int> copies;
  for (const auto& p : split_vertices) ++copies[p];
  for (const auto& p : crack_vertices) EXPECT_EQ(copies[p], 2) << "crack vertex (" << p[0] << ", " << p[1] << ")";
  for (const auto& p : tips) EXPECT_EQ(copies[p], 1) << "tip (" << p[0] << ", " << p[1] << ")";
  EXPECT_EQ(static_cast<long long>(split_vertices.size()), s.summary.heat_vertices + (long long)crack_vertices.size());
  long long expected_tips = 0;
  for (std::size_t c = 0; c < scene.cracks.size(); ++c) {
    mesh::SpecimenGeometry g;
    for (int e = 0; e < 2; ++e) expected_tips += !g.end_on_boundary(scene.cracks[c], e);
  }
  EXPECT_EQ(static_cast<long long>(tips.size()), expected_tips);

  // Sides: the bulk cells on the two faces of a cohesive cell lie on opposite
  // sides of the crack line and share no vertex but tips.
  mesh::VertexCoordinates x;
  x.Setup(wave);
  DMLabel crack_label, tip_label;
  DMGetLabel(wave, mesh::labels::crack, &crack_label);
  DMGetLabel(wave, mesh::labels::crack_tip, &tip_label);
  PetscInt cStart, cEnd;
  DMPlexGetHeightStratum(wave, 0, &cStart, &cEnd);
  long long checked = 0, cohesive = 0;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool is_cohesive;
    mesh::IsCohesiveCell(wave, c, &is_cohesive);
    if (!is_cohesive) continue;
    ++cohesive;
    const PetscInt* cone;
    DMPlexGetCone(wave, c, &cone);
    PetscInt id;
    DMLabelGetValue(crack_label, cone[0], &id);
    const mesh::Crack& k = scene.cracks[id - 1];
    const double t = k.angle_deg * M_PI / 180.0, nx = -std::sin(t), ny = std::cos(t);
    double side[2] = {0, 0};
    std::set<PetscInt> bulk_vertices[2], face_vertices[2];
    bool local = true;
    for (int f = 0; f < 2; ++f) {
      const PetscInt* support;
      PetscInt ns;
      DMPlexGetSupportSize(wave, cone[f], &ns);
      DMPlexGetSupport(wave, cone[f], &support);
      PetscInt bulk = -1;
      for (PetscInt j = 0; j < ns; ++j)
        if (support[j] != c) bulk = support[j];
      if (bulk < 0) {
        local = false;  // the neighbour lives on another rank
        break;
      }
      const auto g = Centroid(wave, x, bulk, &bulk_vertices[f]);
      side[f] = (g[0] - k.x) * nx + (g[1] - k.y) * ny;
      Centroid(wave, x, cone[f], &face_vertices[f]);
    }
    if (!local) continue;
    ++checked;
    EXPECT_LT(side[0] * side[1], 0.0) << "cohesive cell " << c << ": both bulk cells on one side";
    for (int f = 0; f < 2; ++f)
      for (PetscInt v : face_vertices[1 - f]) {
        PetscInt tip;
        DMLabelGetValue(tip_label, v, &tip);
        if (tip != 1) {
          EXPECT_EQ(bulk_vertices[f].count(v), 0u) << "cohesive cell " << c << ": sides not separated";
        }
      }
  }
  EXPECT_GT(Sum(checked), Sum(cohesive) / 2) << "too few cohesive cells had both neighbours local";

  EXPECT_EQ(DMPlexCheckSymmetry(wave), 0);
  EXPECT_EQ(DMPlexCheckSkeleton(wave, 0), 0);
  EXPECT_EQ(DMPlexCheckFaces(wave, 0), 0);
  EXPECT_EQ(DMPlexCheckPointSF(wave, nullptr, PETSC_FALSE), 0);
  EXPECT_EQ(DMPlexCheckSymmetry(heat), 0);
  EXPECT_EQ(DMPlexCheckGeometry(heat), 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, CrackSplit, ::testing::Range(0, static_cast<int>(Scenes().size())));

}  // namespace
}  // namespace vibrotherm::testing

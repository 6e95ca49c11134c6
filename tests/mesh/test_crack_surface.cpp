// Requirement: each mesh's crack surface lists every crack facet exactly once
// over the ranks (wave mesh: one per cohesive cell, its − face; heat mesh: the
// owned labelled facets), the same list on every rank; its owned entries name
// the mesh points they came from; a crack's polyline (ξ) has the same ends and
// length on both meshes and is as long as its facets; the facet frames are
// orthonormal with n = t turned +90°. Serial and 2 ranks.
#include <cmath>
#include <set>

#include "mesh_test_support.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"

namespace vibrotherm::testing {
namespace {

const std::vector<std::string>& SurfaceScenes() {
  static const std::vector<std::string> scenes = {
      "-specimen_width 0.05 -specimen_height 0.1 -mesh_h 0.004 -crack_center 0.015,0.025,0.03,0.05 "
      "-crack_length 0.01,0.015 -crack_angle 0,45",
      "-specimen_width 0.05 -specimen_height 0.1 -mesh_h 0.004 -crack_center 0.008660254037844386,0.05 "
      "-crack_length 0.02 -crack_angle 30 -mesh_cell tri -heat_mesh wave",
  };
  return scenes;
}

/// Each id once, the owned entries matching their mesh points' labels.
void ExpectFacetsOnce(DM dm, const mesh::CrackSurface& surface, bool split) {
  std::set<long> ids;
  for (const geometry::CrackFacet& f : surface.facets()) EXPECT_TRUE(ids.insert(f.id).second) << "id " << f.id;
  EXPECT_EQ(ids.size(), surface.facets().size());
  if (!ids.empty()) {
    EXPECT_EQ(*ids.rbegin() + 1, static_cast<long>(ids.size())) << "ids 0 .. n − 1";
  }
  long owned = static_cast<long>(surface.owned().size());
  MPI_Allreduce(MPI_IN_PLACE, &owned, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(owned, static_cast<long>(surface.facets().size()));
  DMLabel id_label;
  DMGetLabel(dm, mesh::labels::crack_face, &id_label);
  for (const mesh::OwnedCrackFacet& o : surface.owned()) {
    PetscInt id;
    DMLabelGetValue(id_label, o.facet, &id);
    EXPECT_EQ(id, surface.facets().at(o.index).id);
    bool cohesive;
    mesh::IsCohesiveCell(dm, o.cell, &cohesive);
    EXPECT_EQ(cohesive, split);
    if (split) {
      const PetscInt* cone;
      DMPlexGetCone(dm, o.cell, &cone);
      EXPECT_EQ(cone[0], o.facet) << "the − face";
    }
  }
}

class CrackSurface : public ::testing::TestWithParam<int> {};

TEST_P(CrackSurface, GathersEveryFacetOnceOnBothMeshes) {
  ScopedSpecimen s(SurfaceScenes()[GetParam()]);
  ASSERT_EQ(s.status, 0);
  const mesh::CrackSurface &wave = s.specimen.wave_cracks, &heat = s.specimen.heat_cracks;
  ASSERT_EQ(wave.crack_count(), static_cast<PetscInt>(s.specimen.cracks.size()));
  ExpectFacetsOnce(s.specimen.wave, wave, true);
  ExpectFacetsOnce(s.specimen.heat, heat, false);
  for (PetscInt k = 0; k < wave.crack_count(); ++k) {
    const mesh::CrackLine &a = wave.line(k), &b = heat.line(k);
    const double L = a.length();
    EXPECT_NEAR(b.length(), L, 1e-9 * L) << "crack " << k;
    for (double xi : {0.0, 1.0})
      EXPECT_LT(std::hypot(a.At(xi)[0] - b.At(xi)[0], a.At(xi)[1] - b.At(xi)[1]), 1e-9 * L) << "ξ = " << xi;
    double facets = 0.0;
    for (const geometry::CrackFacet& f : wave.facets())
      if (f.crack == k) facets += geometry::Measure(f);
    EXPECT_NEAR(facets, L, 1e-12 * L);
  }
}

TEST_P(CrackSurface, FacetFramesAreOrthonormal) {
  ScopedSpecimen s(SurfaceScenes()[GetParam()]);
  ASSERT_EQ(s.status, 0);
  for (const geometry::CrackFacet& f : s.specimen.wave_cracks.facets()) {
    const geometry::Frame<2> frame = mesh::CrackSurface::FacetFrame(f);
    EXPECT_NEAR(geometry::Norm(frame.tangent[0]), 1.0, 1e-14);
    EXPECT_NEAR(geometry::Dot(frame.tangent[0], frame.normal), 0.0, 1e-14);
    EXPECT_EQ(frame.normal, geometry::LeftNormal(frame.tangent[0]));
    const geometry::Vec2 chord = geometry::Sub(f.p1, f.p0);
    EXPECT_NEAR(geometry::Dot(chord, frame.tangent[0]), geometry::Measure(f), 1e-12 * geometry::Measure(f));
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, CrackSurface, ::testing::Range(0, static_cast<int>(SurfaceScenes().size())));

}  // namespace
}  // namespace vibrotherm::testing

// Requirement (issue 39, item 2: friction heat by one surface quadrature in both dimensions):
// in 2D the crack faces' quadrature (crack_face_quadrature.hpp), its segments cut at the heat
// mesh's crack vertices, gives the friction-heat transfer T (heat dofs × contact cells) that
// the exact line integrals over every overlap of a wave and a heat crack element give
// (line_transfer.hpp, the oracle; its own closed-form tests: test_line_transfer.cpp), on a
// graded heat mesh whose crack vertices do not nest in the wave mesh's: Q2 quads with a Q2
// heat, Q1 triangles with a Q1 heat. FrictionHeat uses that transfer. A control: without the
// cuts the same quadrature is not exact. Serial and 2 ranks (the oracle's heat elements are
// each rank's owned crack facets; T^T w for a heat vector w compared cell by cell).
#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "vibrotherm/coupling/exchange/crack_face_quadrature.hpp"
#include "vibrotherm/coupling/exchange/friction_heat.hpp"
#include "vibrotherm/coupling/exchange/surface_transfer.hpp"
#include "vibrotherm/util/all_gather.hpp"
#include "wave_test_support.hpp"

namespace vibrotherm::testing {
namespace {

const std::string kPaper = std::string("-options_file ") + VIBROTHERM_SOURCE_DIR + "/options/paper.opts ";

/// The oracle's heat crack elements: each owned crack facet of the heat mesh, its nodes the
/// global rows of its end vertices (in the crack line's direction) and of its middle (Q2).
PetscErrorCode HeatCrackElements(const fe::LagrangeSpace& heat, const mesh::CrackSurface& cracks,
                                 std::vector<coupling::CrackElement>* elements) {
  PetscFunctionBeginUser;
  PetscSection global;
  PetscCall(DMGetGlobalSection(heat.dm(), &global));
  const auto row = [&](PetscInt point) {
    PetscInt off = -1;
    EXPECT_EQ(PetscSectionGetOffset(global, point, &off), 0);
    return static_cast<long>(off >= 0 ? off : -(off + 1));
  };
  for (const mesh::OwnedCrackFacet& owned : cracks.owned()) {
    const geometry::CrackFacet& facet = cracks.facets()[owned.index];
    const mesh::CrackLine& line = cracks.line(facet.crack);
    const auto& ids = line.facet_ids();
    const std::size_t j = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), facet.id) - ids.begin());
    PetscCheck(j < ids.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "crack facet %ld is not on its crack line", facet.id);
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(heat.dm(), owned.facet, &cone));
    const auto v = line.vertex(j);
    const bool forward = std::hypot(facet.p0[0] - v[0], facet.p0[1] - v[1]) < 1e-9 * line.length();
    coupling::CrackElement e;
    e.crack = facet.crack;
    e.xi0 = line.vertex_xi(j);
    e.xi1 = line.vertex_xi(j + 1);
    e.degree = static_cast<int>(heat.degree());
    e.node = {row(cone[forward ? 0 : 1]), row(cone[forward ? 1 : 0]), e.degree == 2 ? row(owned.facet) : -1};
    elements->push_back(e);
  }
  PetscFunctionReturn(0);
}

/// A heat vector with a different value at every global row: w_h = sin(1.7 h + 0.3).
PetscErrorCode Probe(DM dm, Vec* w) {
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dm, w));
  PetscInt lo, hi;
  PetscCall(VecGetOwnershipRange(*w, &lo, &hi));
  for (PetscInt h = lo; h < hi; ++h) PetscCall(VecSetValue(*w, h, std::sin(1.7 * h + 0.3), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(*w));
  PetscCall(VecAssemblyEnd(*w));
  PetscFunctionReturn(0);
}

/// (T^T w)_c of every contact cell, by the oracle's entries (rows: global heat rows).
std::vector<double> OracleResponse(const std::vector<coupling::TransferEntry>& entries, Vec w, std::size_t cells) {
  Vec all;
  VecScatter to_all;
  VecScatterCreateToAll(w, &to_all, &all);
  VecScatterBegin(to_all, w, all, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(to_all, w, all, INSERT_VALUES, SCATTER_FORWARD);
  const PetscScalar* x;
  VecGetArrayRead(all, &x);
  std::vector<double> response(cells, 0.0);
  for (const coupling::TransferEntry& t : entries) response[t.col] += t.value * PetscRealPart(x[t.row]);
  VecRestoreArrayRead(all, &x);
  VecScatterDestroy(&to_all);
  VecDestroy(&all);
  MPI_Allreduce(MPI_IN_PLACE, response.data(), static_cast<int>(cells), MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return response;
}

/// (T^T w)_c of every contact cell for the quadrature's T = Ψ Φ (with or without the cuts).
std::vector<double> QuadratureResponse(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave,
                                       const fe::LagrangeSpace& heat, const coupling::CrackFaceSplit& split, Vec w) {
  coupling::SurfacePoints points;
  Mat basis, T;
  EXPECT_EQ(coupling::BuildCrackFaceQuadrature(crack, wave, split, &points, &basis), 0);
  coupling::SurfaceHeatTransfer psi;
  EXPECT_EQ(psi.Setup(heat, points), 0);
  MatMatMult(psi.matrix(), basis, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &T);
  Vec r;
  MatCreateVecs(T, &r, nullptr);
  MatMultTranspose(T, w, r);
  const PetscScalar* x;
  PetscInt n;
  VecGetLocalSize(r, &n);
  VecGetArrayRead(r, &x);
  std::vector<double> mine(x, x + n), all;
  VecRestoreArrayRead(r, &x);
  VecDestroy(&r);
  MatDestroy(&T);
  MatDestroy(&basis);
  util::AllGather(PETSC_COMM_WORLD, mine, &all);
  return all;
}

/// max |a − b| / max |b|.
double RelativeMisfit(const std::vector<double>& a, const std::vector<double>& b) {
  double error = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    error = std::max(error, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return error / scale;
}

struct Case {
  const char* name;
  const char* options;
  int heat_degree;
};

class FrictionHeatQuadrature2D : public ::testing::TestWithParam<Case> {};

TEST_P(FrictionHeatQuadrature2D, EqualsTheExactLineIntegralsOnAHeatMeshThatDoesNotNest) {
  const Case& c = GetParam();
  ScopedWave w(kPaper + c.options + " -mesh_h 0.004 -mesh_h_crack 0.0011 -heat_mesh_h_crack 0.0004"
               " -heat_mesh_h_along 0.0007");
  ASSERT_EQ(w.status, 0);
  const mesh::Specimen& specimen = w.specimen->specimen;
  contact::ContactParameters params;
  params.crack_law = "mmd";
  interface::CrackInterface crack;
  ASSERT_EQ(crack.Setup(w.solver.space(), specimen.wave_cracks, w.solver.op().mass(), contact::create_crack_law(params),
                        interface::ApproachProfile{}),
            0);
  fe::LagrangeSpace heat;
  ASSERT_EQ(heat.Setup(specimen.heat, c.heat_degree, 1), 0);
  coupling::FrictionHeat friction;
  ASSERT_EQ(friction.Setup(crack, w.solver.space(), specimen.wave_cracks, heat, specimen.heat_cracks,
                           specimen.crack_face_subdivisions),
            0);
  std::vector<coupling::CrackElement> heat_elements;
  ASSERT_EQ(HeatCrackElements(heat, specimen.heat_cracks, &heat_elements), 0);
  const auto entries = coupling::LineTransferEntries(heat_elements, friction.wave_elements());
  Vec probe;
  ASSERT_EQ(Probe(heat.dm(), &probe), 0);
  const std::vector<double> oracle = OracleResponse(entries, probe, static_cast<std::size_t>(crack.global_cells()));

  const coupling::CrackFaceSplit cut{1, coupling::CrackLineVertices(specimen.heat_cracks)};
  const double cut_misfit = RelativeMisfit(QuadratureResponse(crack, w.solver.space(), heat, cut, probe), oracle);
  EXPECT_LT(cut_misfit, 1e-12);
  std::vector<double> mine, used;
  ASSERT_EQ(friction.CellResponse(probe, &mine), 0);
  ASSERT_EQ(util::AllGather(PETSC_COMM_WORLD, mine, &used), 0);
  EXPECT_LT(RelativeMisfit(used, oracle), 1e-12) << "FrictionHeat's transfer is the cut quadrature";
  const coupling::CrackFaceSplit uncut{1, {}};
  const double uncut_misfit = RelativeMisfit(QuadratureResponse(crack, w.solver.space(), heat, uncut, probe), oracle);
  EXPECT_GT(uncut_misfit, 1e-6) << "control: uncut, the heat basis kinks inside the pieces and the rule is not exact";
  PetscPrintf(PETSC_COMM_WORLD, "T^T w against the line integrals: cut %.2e, uncut %.2e (%zu oracle entries)\n",
              cut_misfit, uncut_misfit, entries.size());
  VecDestroy(&probe);
}

INSTANTIATE_TEST_SUITE_P(FrictionHeat2D, FrictionHeatQuadrature2D,
                         ::testing::Values(Case{"QuadsQ2", "-wave_degree 2", 2},
                                           Case{"TrianglesQ1", "-mesh_cell tri -wave_degree 1", 1}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vibrotherm::testing

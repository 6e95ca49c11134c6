// Requirement: the crack interface built on the split mesh has one contact cell
// per crack node (Q2: vertices and mid-sides, buried tips excluded), tributary
// lengths that sum to the crack length (but the buried tips' share), normals from the − face into the + body
// (the + point's bulk cell lies along n), the same cells on any number of ranks;
// and a Simulation built in-process (paper scene, a few periods) deposits in the
// heat exactly the energy the crack dissipated. Serial and 2 ranks.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/coupling/run/simulation.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "wave_test_support.hpp"

namespace vibrotherm::testing {
namespace {

const std::string kPaper = std::string("-options_file ") + VIBROTHERM_SOURCE_DIR + "/options/paper.opts ";

/// The crack interface on the scene's wave mesh, with the named law.
PetscErrorCode SetUpCrack(ScopedWave& w, const char* law, const interface::ApproachProfile& a0,
                          interface::CrackInterface* crack) {
  contact::ContactParameters params;
  params.crack_law = law;
  return crack->Setup(w.solver.space(), w.specimen->specimen.wave_cracks, w.solver.op().mass(),
                      contact::create_crack_law(params), a0);
}

TEST(CrackInterface, CellsFollowTheGeometry) {
  ScopedWave w(kPaper + "-mesh_h 0.004");
  ASSERT_EQ(w.status, 0);
  interface::CrackInterface crack;
  ASSERT_EQ(SetUpCrack(w, "mmd", interface::ApproachProfile{}, &crack), 0);
  const PetscInt facets = w.specimen->summary.cracks.at(0).facets;
  EXPECT_EQ(crack.global_cells(), 2 * facets - 1) << "Q2: facets − 1 vertex pairs and a mid-side pair per facet";
  const double theta = 20.0 * M_PI / 180.0;
  double weights = 0.0;
  for (const interface::ContactCell& c : crack.cells()) {
    weights += c.weight;
    EXPECT_NEAR(c.s[0], std::cos(theta), 1e-9);
    EXPECT_NEAR(c.s[1], std::sin(theta), 1e-9);
    EXPECT_NEAR(c.n[0], -std::sin(theta), 1e-9);
    EXPECT_NEAR(c.n[1], std::cos(theta), 1e-9);
    EXPECT_GE(c.xi, 0.0);
    EXPECT_LE(c.xi, 1.0);
    // Away from the crack along +n lies the + side: the + point is not the − point.
    EXPECT_NE(c.plus, c.minus);
  }
  MPI_Allreduce(MPI_IN_PLACE, &weights, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  // Buried tips carry no contact cell: their sixth of the end facets (Q2) is all that is missing.
  const double tip_facet = 0.02 / static_cast<double>(facets);  // gmsh divides the straight crack evenly
  EXPECT_NEAR(weights, 0.02 - 2.0 * tip_facet / 6.0, 1e-12) << "tributary lengths sum to the crack length";
}

/// Every bulk cell around each contact cell's + point lies on the + side of the crack (along n
/// from the point): the + side the split labelled (crack_plus) is the one n points into.
void ExpectPlusSideAlongN(const fe::LagrangeSpace& space, const interface::CrackInterface& crack) {
  DM dm = space.dm();
  mesh::VertexCoordinates x;
  ASSERT_EQ(x.Setup(dm), 0);
  PetscInt cStart, cEnd;
  DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd);
  int checked = 0;
  for (const interface::ContactCell& c : crack.cells()) {
    PetscInt n_star, *star = nullptr;
    DMPlexGetTransitiveClosure(dm, c.plus, PETSC_FALSE, &n_star, &star);
    for (PetscInt k = 0; k < n_star; ++k) {
      const PetscInt cell = star[2 * k];
      bool cohesive;
      if (cell < cStart || cell >= cEnd || mesh::IsCohesiveCell(dm, cell, &cohesive) != 0 || cohesive) continue;
      std::array<double, 2> centre{};
      EXPECT_EQ(mesh::CellCentroid(dm, x, cell, &centre), 0);
      EXPECT_GT((centre[0] - c.x) * c.n[0] + (centre[1] - c.y) * c.n[1], 0.0)
          << "cell " << cell << " around the + point of the contact cell at (" << c.x << ", " << c.y << ")";
      ++checked;
    }
    DMPlexRestoreTransitiveClosure(dm, c.plus, PETSC_FALSE, &n_star, &star);
  }
  MPI_Allreduce(MPI_IN_PLACE, &checked, 1, MPI_INT, MPI_SUM, PetscObjectComm((PetscObject)dm));
  EXPECT_GT(checked, 0);
}

TEST(CrackInterface, ThePlusPointsBulkLiesAlongN) {
  // A crack rising and one falling along x (its chord runs from the end with the smaller x).
  for (const char* angle : {"20", "-70"}) {
    ScopedWave w(kPaper + "-mesh_h 0.004 -crack_angle " + angle);
    ASSERT_EQ(w.status, 0);
    interface::CrackInterface crack;
    ASSERT_EQ(SetUpCrack(w, "mmd", interface::ApproachProfile{}, &crack), 0);
    // n: the tangent from the end with the smaller x, (cos θ, sin θ), turned by +90°.
    const double theta = std::atof(angle) * M_PI / 180.0;
    for (const interface::ContactCell& c : crack.cells()) {
      EXPECT_NEAR(c.n[0], -std::sin(theta), 1e-9);
      EXPECT_NEAR(c.n[1], std::cos(theta), 1e-9);
    }
    ExpectPlusSideAlongN(w.solver.space(), crack);
  }
}

TEST(CrackInterface, OpeningTheCrackPullsThePlusFaceAlongN) {
  // A pre-closed crack (a0 > 0) pushed further closed by a jump against n feels a
  // restoring force along +n on the + face: the sign convention of PHYSICS.md §3.1.
  ScopedWave w(kPaper + "-mesh_h 0.004");
  ASSERT_EQ(w.status, 0);
  interface::ApproachProfile a0;
  a0.uniform = 1e-8;
  interface::CrackInterface crack;
  ASSERT_EQ(SetUpCrack(w, "clapping", a0, &crack), 0);
  Vec u, acc;
  ASSERT_EQ(VecDuplicate(w.solver.op().mass(), &u), 0);
  ASSERT_EQ(VecDuplicate(u, &acc), 0);
  VecSet(acc, 0.0);
  PetscSection global;
  DMGetGlobalSection(w.solver.space().dm(), &global);
  VecSet(u, 0.0);
  for (const interface::ContactCell& c : crack.cells()) {  // + face moved by −n·1e-9: the faces press harder
    PetscInt off;
    PetscSectionGetOffset(global, c.plus, &off);
    if (off >= 0) {
      VecSetValue(u, off, -1e-9 * c.n[0], INSERT_VALUES);
      VecSetValue(u, off + 1, -1e-9 * c.n[1], INSERT_VALUES);
    }
  }
  VecAssemblyBegin(u);
  VecAssemblyEnd(u);
  ASSERT_EQ(crack.AddAcceleration(u, acc), 0);
  const PetscScalar* a;
  PetscInt rstart;
  VecGetOwnershipRange(acc, &rstart, nullptr);
  VecGetArrayRead(acc, &a);
  for (const interface::ContactCell& c : crack.cells()) {
    PetscInt off;
    PetscSectionGetOffset(global, c.plus, &off);
    if (off < 0) continue;
    const double along_n = PetscRealPart(a[off - rstart]) * c.n[0] + PetscRealPart(a[off - rstart + 1]) * c.n[1];
    EXPECT_GT(along_n, 0.0) << "cell at (" << c.x << ", " << c.y << ")";
  }
  VecRestoreArrayRead(acc, &a);
  VecDestroy(&u);
  VecDestroy(&acc);
}

TEST(Simulation, HeatReceivesExactlyTheDissipatedEnergy) {
  ScopedSpecimen s(kPaper + "-mesh_h 0.004 -final_time 5e-5 -output_times 5e-5 -crack_state_every 0");
  ASSERT_EQ(s.status, 0);
  coupling::Scene scene;
  ASSERT_EQ(coupling::ReadScene(PETSC_COMM_WORLD, &scene), 0);
  io::RunSummary summary;
  coupling::Simulation simulation;
  ASSERT_EQ(simulation.Setup(s.specimen, scene, &summary), 0);
  char dir[] = "/tmp/vibrotherm_simulation_XXXXXX";
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    ASSERT_NE(mkdtemp(dir), nullptr);
  }
  MPI_Bcast(dir, sizeof(dir), MPI_CHAR, 0, PETSC_COMM_WORLD);
  ASSERT_EQ(simulation.Run(dir, &summary, coupling::RunControl{}), 0);
  EXPECT_EQ(summary.physics_ran, (std::vector<std::string>{"wave", "contact", "heat"}));
  EXPECT_GT(summary.dissipated_energy, 0.0);
  EXPECT_NEAR(summary.heat_deposited, summary.dissipated_energy, 1e-12 * summary.dissipated_energy);
  EXPECT_NEAR(summary.heat_content, summary.heat_deposited - summary.heat_boundary_loss, 1e-10 * summary.heat_deposited);
}

}  // namespace
}  // namespace vibrotherm::testing

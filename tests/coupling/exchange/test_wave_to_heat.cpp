// Requirement (issues 23 and 26: thermoelastic coupling and damping heat in 2D and 3D): the
// wave-to-heat transfer integrates exactly what it should over a heat mesh that does not
// match the wave mesh. On distorted quads/hexes and on triangles/tetrahedra (wave degree
// 1 and 2) and a heat grid of other cells (their quadrature points fall anywhere in the
// wave cells, several wave cells under one heat cell):
//  - B u = −T0β tr(G) ∫ψ_h for an affine displacement u = G x + c with a full G (the wave
//    space reproduces it, so ∇·u = tr G at every point): the inverse Jacobian's every entry
//    and every displacement component count, and every heat point is found once;
//  - the damping kernel (φ) applied to a unit displacement gives dim ∫ψ_h (Σ_a φ_a = 1).
// And on ranks (issue 40, item 4: the heat points go by a PetscSF to the ranks whose wave
// cells' box holds them, no all-gather), both meshes in slabs: the transfer is the serial one
// (its entries' sum and norm) and exact on an affine field, every point owned once, no rank
// receives every point, and a heat point in no wave cell is still the error it was.
#include <array>
#include <cmath>

#include "box_mesh_support.hpp"
#include "vibrotherm/coupling/exchange/thermoelastic_transfer.hpp"

namespace vibrotherm::testing {
namespace {

/// ∫ψ_h of every heat node (global vector), with the heat space's own quadrature.
PetscErrorCode BasisIntegrals(const fe::LagrangeSpace& heat, Vec* integrals) {
  PetscFunctionBeginUser;
  PetscSection section;
  PetscCall(DMGetLocalSection(heat.dm(), &section));
  Vec local;
  PetscCall(DMGetLocalVector(heat.dm(), &local));
  PetscCall(VecSet(local, 0.0));
  fe::CellQuadrature q;
  std::vector<double> element(heat.nodes_per_cell());
  for (PetscInt c : heat.cells()) {
    PetscCall(heat.Evaluate(c, &q));
    for (int b = 0; b < q.nodes; ++b) {
      element[b] = 0.0;
      for (int p = 0; p < q.points; ++p) element[b] += q.weight[p] * q.value[p * q.nodes + b];
    }
    PetscCall(DMPlexVecSetClosure(heat.dm(), section, local, c, element.data(), ADD_VALUES));
  }
  PetscCall(DMCreateGlobalVector(heat.dm(), integrals));
  PetscCall(VecSet(*integrals, 0.0));
  PetscCall(DMLocalToGlobal(heat.dm(), local, ADD_VALUES, *integrals));
  PetscCall(DMRestoreLocalVector(heat.dm(), &local));
  PetscFunctionReturn(0);
}

/// max |T u − expected ∫ψ_h| relative to max |expected ∫ψ_h| (integrals: ∫ψ_h).
double RelativeMisfit(Mat T, Vec u, Vec integrals, double expected) {
  Vec Tu, want;
  MatCreateVecs(T, nullptr, &Tu);
  MatMult(T, u, Tu);
  VecDuplicate(integrals, &want);
  VecCopy(integrals, want);
  VecScale(want, expected);
  PetscReal scale, error;
  VecNorm(want, NORM_INFINITY, &scale);
  VecAXPY(Tu, -1.0, want);
  VecNorm(Tu, NORM_INFINITY, &error);
  VecDestroy(&Tu);
  VecDestroy(&want);
  return error / scale;
}

/// An affine displacement u = G x + c with a full G on the wave space; its divergence tr G.
PetscErrorCode AffineDisplacement(const fe::LagrangeSpace& wave, Vec* u, double* trace) {
  const int dim = wave.dim();
  const double G[3][3] = {{0.7, -0.4, 0.25}, {0.3, -1.1, 0.6}, {-0.5, 0.45, 0.9}}, c[3] = {0.2, -0.1, 0.3};
  *trace = 0.0;
  for (int d = 0; d < dim; ++d) *trace += G[d][d];
  return NodalField(wave, [&](const double* x, double* v) {
    for (int i = 0; i < dim; ++i) {
      v[i] = c[i];
      for (int j = 0; j < dim; ++j) v[i] += G[i][j] * x[j];
    }
  }, u);
}

class WaveToHeat : public ::testing::TestWithParam<BoxCase> {
 protected:
  void SetUp() override {
    const BoxCase& c = GetParam();
    ASSERT_EQ(BoxMesh(c, &wave_dm_), 0);
    ASSERT_EQ(wave_.Setup(wave_dm_, c.degree, c.dim), 0);
    // The heat grid: straight quads/hexes of other sizes than the wave cells.
    const PetscInt faces[3] = {4, 3, 3};
    const PetscReal lower[3] = {0, 0, 0}, upper[3] = {kBoxUpper[0], kBoxUpper[1], kBoxUpper[2]};
    ASSERT_EQ(DMPlexCreateBoxMesh(PETSC_COMM_SELF, c.dim, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE,
                                  &heat_dm_), 0);
    ASSERT_EQ(heat_.Setup(heat_dm_, 1, 1), 0);
    ASSERT_EQ(BasisIntegrals(heat_, &integrals_), 0);
  }
  void TearDown() override {
    VecDestroy(&integrals_);
    DMDestroy(&wave_dm_);
    DMDestroy(&heat_dm_);
  }
  double Misfit(Mat T, Vec u, double expected) { return RelativeMisfit(T, u, integrals_, expected); }
  DM wave_dm_ = nullptr, heat_dm_ = nullptr;
  fe::LagrangeSpace wave_, heat_;
  Vec integrals_ = nullptr;
};

TEST_P(WaveToHeat, ThermoelasticTransferTakesTheDivergenceOfAnAffineDisplacement) {
  Vec u;
  double trace;
  ASSERT_EQ(AffineDisplacement(wave_, &u, &trace), 0);
  const double beta_T0 = 3.7;
  Mat B;
  ASSERT_EQ(coupling::AssembleThermoelasticTransfer(wave_, heat_, beta_T0, &B), 0);
  EXPECT_LT(Misfit(B, u, -beta_T0 * trace), 1e-12);
  MatDestroy(&B);
  VecDestroy(&u);
}

TEST_P(WaveToHeat, DampingKernelSumsTheWaveBasisToOne) {
  const int dim = GetParam().dim;
  Vec u;
  ASSERT_EQ(NodalField(wave_, [&](const double*, double* v) {
    for (int i = 0; i < dim; ++i) v[i] = 1.0;
  }, &u), 0);
  Mat T;
  ASSERT_EQ(coupling::AssembleWaveToHeat(wave_, heat_, [](double phi, double) { return phi; }, &T), 0);
  EXPECT_LT(Misfit(T, u, dim), 1e-12);
  MatDestroy(&T);
  VecDestroy(&u);
}

INSTANTIATE_TEST_SUITE_P(Boxes, WaveToHeat, ::testing::ValuesIn(AllBoxCases()), BoxCaseName);

/// The box [0, kBoxUpper × scale] of faces cells on comm; on several ranks distributed by the simple
/// partitioner (cells in their order: each rank a slab across the last axis, apart from the others).
PetscErrorCode SlabBox(MPI_Comm comm, int dim, const PetscInt* faces, double scale, DM* dm) {
  PetscFunctionBeginUser;
  const PetscReal lower[3] = {0, 0, 0};
  const PetscReal upper[3] = {scale * kBoxUpper[0], scale * kBoxUpper[1], scale * kBoxUpper[2]};
  PetscCall(DMPlexCreateBoxMesh(comm, dim, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, dm));
  PetscPartitioner partitioner;
  PetscCall(DMPlexGetPartitioner(*dm, &partitioner));
  PetscCall(PetscPartitionerSetType(partitioner, PETSCPARTITIONERSIMPLE));
  DM distributed = nullptr;
  PetscCall(DMPlexDistribute(*dm, 0, nullptr, &distributed));
  if (distributed) {
    PetscCall(DMDestroy(dm));
    *dm = distributed;
  }
  PetscFunctionReturn(0);
}

/// Σ of T's entries and its Frobenius norm: the same whatever the numbering of rows and columns.
std::array<double, 2> Invariants(Mat T) {
  Vec ones, Tones;
  MatCreateVecs(T, &ones, &Tones);
  VecSet(ones, 1.0);
  MatMult(T, ones, Tones);
  PetscScalar sum;
  PetscReal norm;
  VecSum(Tones, &sum);
  MatNorm(T, NORM_FROBENIUS, &norm);
  VecDestroy(&ones);
  VecDestroy(&Tones);
  return {PetscRealPart(sum), norm};
}

/// Wave (Q2) and heat (Q1) box meshes of other cells, each in slabs over the ranks (issue 40,
/// item 4): the transfer is the one serial meshes give, and the heat points do not all reach
/// every rank (they went to the ranks whose wave cells' box holds them, not by an all-gather).
class WaveToHeatOnRanks : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    const int dim = GetParam();
    ASSERT_EQ(SlabBox(PETSC_COMM_WORLD, dim, kWaveFaces, 1.0, &wave_dm_), 0);
    ASSERT_EQ(SlabBox(PETSC_COMM_WORLD, dim, kHeatFaces, 1.0, &heat_dm_), 0);
    ASSERT_EQ(wave_.Setup(wave_dm_, 2, dim), 0);
    ASSERT_EQ(heat_.Setup(heat_dm_, 1, 1), 0);
  }
  void TearDown() override {
    DMDestroy(&wave_dm_);
    DMDestroy(&heat_dm_);
  }
  static constexpr PetscInt kWaveFaces[3] = {5, 4, 6}, kHeatFaces[3] = {4, 3, 7};
  DM wave_dm_ = nullptr, heat_dm_ = nullptr;
  fe::LagrangeSpace wave_, heat_;
};

TEST_P(WaveToHeatOnRanks, EqualsTheSerialTransferAndNoRankSeesEveryPoint) {
  const int dim = GetParam();
  const double beta_T0 = 3.7;
  Mat B;
  util::ExchangeCounts counts;
  ASSERT_EQ(coupling::AssembleWaveToHeat(wave_, heat_, [&](double, double d) { return -beta_T0 * d; }, &B, &counts),
            0);
  // The divergence of an affine displacement, exact: every heat point assembled once.
  Vec u, integrals;
  double trace;
  ASSERT_EQ(AffineDisplacement(wave_, &u, &trace), 0);
  ASSERT_EQ(BasisIntegrals(heat_, &integrals), 0);
  EXPECT_LT(RelativeMisfit(B, u, integrals, -beta_T0 * trace), 1e-12);
  // The same meshes whole on this rank: the same matrix up to numbering (and summation order).
  DM wave_dm, heat_dm;
  fe::LagrangeSpace wave, heat;
  Mat serial;
  ASSERT_EQ(SlabBox(PETSC_COMM_SELF, dim, kWaveFaces, 1.0, &wave_dm), 0);
  ASSERT_EQ(SlabBox(PETSC_COMM_SELF, dim, kHeatFaces, 1.0, &heat_dm), 0);
  ASSERT_EQ(wave.Setup(wave_dm, 2, dim), 0);
  ASSERT_EQ(heat.Setup(heat_dm, 1, 1), 0);
  ASSERT_EQ(coupling::AssembleThermoelasticTransfer(wave, heat, beta_T0, &serial), 0);
  const std::array<double, 2> mine = Invariants(B), want = Invariants(serial);
  EXPECT_NEAR(mine[0], want[0], 1e-12 * want[1]);
  EXPECT_NEAR(mine[1], want[1], 1e-12 * want[1]);
  // Each point owned once; on several ranks, none received them all.
  unsigned long long owned = counts.owned, points = counts.mine, all_owned = 0, all_points = 0;
  MPI_Allreduce(&owned, &all_owned, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  MPI_Allreduce(&points, &all_points, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(all_owned, static_cast<unsigned long long>(counts.total));
  EXPECT_EQ(all_points, static_cast<unsigned long long>(counts.total));
  PetscMPIInt size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size > 1) {
    EXPECT_LT(counts.received, static_cast<std::size_t>(counts.total));
  } else {
    EXPECT_EQ(counts.received, static_cast<std::size_t>(counts.total));
  }
  for (Mat* M : {&B, &serial}) MatDestroy(M);
  VecDestroy(&u);
  VecDestroy(&integrals);
  DMDestroy(&wave_dm);
  DMDestroy(&heat_dm);
}

TEST_P(WaveToHeatOnRanks, AHeatPointInNoWaveCellIsAnError) {
  DM big_dm;  // a heat mesh reaching beyond the wave mesh
  fe::LagrangeSpace big;
  ASSERT_EQ(SlabBox(PETSC_COMM_WORLD, GetParam(), kHeatFaces, 1.1, &big_dm), 0);
  ASSERT_EQ(big.Setup(big_dm, 1, 1), 0);
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  Mat B = nullptr;
  EXPECT_EQ(coupling::AssembleThermoelasticTransfer(wave_, big, 1.0, &B), PETSC_ERR_PLIB);
  PetscPopErrorHandler();
  DMDestroy(&big_dm);
}

INSTANTIATE_TEST_SUITE_P(Dims, WaveToHeatOnRanks, ::testing::Values(2, 3));

}  // namespace
}  // namespace vibrotherm::testing

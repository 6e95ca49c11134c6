// Requirement (issues 23 and 26: thermoelastic coupling and damping heat in 2D and 3D): the
// wave-to-heat transfer integrates exactly what it should over a heat mesh that does not
// match the wave mesh. On distorted quads/hexes and on triangles/tetrahedra (wave degree
// 1 and 2) and a heat grid of other cells (their quadrature points fall anywhere in the
// wave cells, several wave cells under one heat cell):
//  - B u = −T0β tr(G) ∫ψ_h for an affine displacement u = G x + c with a full G (the wave
//    space reproduces it, so ∇·u = tr G at every point): the inverse Jacobian's every entry
//    and every displacement component count, and every heat point is found once;
//  - the damping kernel (φ) applied to a unit displacement gives dim ∫ψ_h (Σ_a φ_a = 1).
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
  /// max |T u − expected ∫ψ_h| relative to max |expected ∫ψ_h|.
  double Misfit(Mat T, Vec u, double expected) {
    Vec Tu, want;
    MatCreateVecs(T, nullptr, &Tu);
    MatMult(T, u, Tu);
    VecDuplicate(integrals_, &want);
    VecCopy(integrals_, want);
    VecScale(want, expected);
    PetscReal scale, error;
    VecNorm(want, NORM_INFINITY, &scale);
    VecAXPY(Tu, -1.0, want);
    VecNorm(Tu, NORM_INFINITY, &error);
    VecDestroy(&Tu);
    VecDestroy(&want);
    return error / scale;
  }
  DM wave_dm_ = nullptr, heat_dm_ = nullptr;
  fe::LagrangeSpace wave_, heat_;
  Vec integrals_ = nullptr;
};

TEST_P(WaveToHeat, ThermoelasticTransferTakesTheDivergenceOfAnAffineDisplacement) {
  const int dim = GetParam().dim;
  const double G[3][3] = {{0.7, -0.4, 0.25}, {0.3, -1.1, 0.6}, {-0.5, 0.45, 0.9}}, c[3] = {0.2, -0.1, 0.3};
  double trace = 0.0;
  for (int d = 0; d < dim; ++d) trace += G[d][d];
  Vec u;
  ASSERT_EQ(NodalField(wave_, [&](const double* x, double* v) {
    for (int i = 0; i < dim; ++i) {
      v[i] = c[i];
      for (int j = 0; j < dim; ++j) v[i] += G[i][j] * x[j];
    }
  }, &u), 0);
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

}  // namespace
}  // namespace vibrotherm::testing

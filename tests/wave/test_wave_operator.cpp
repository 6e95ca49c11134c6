// Requirement (issue 42, the wave solver split by concern): the elastic operator stands
// alone, without a time integrator, on every box mesh (2D/3D, quads/simplices, Q1/Q2):
//  - its dimension and dof count are the DM's;
//  - ω_max (SLEPc) is the top of the spectrum of M⁻¹K: above every Rayleigh quotient
//    xᵀKx / xᵀMx of a power iteration, within 10 % of its last one, and below
//    Gershgorin's bound max_i Σ_j |K_ij| / M_i;
//  - A = −M⁻¹K is M-self-adjoint (yᵀM(Ax) = xᵀM(Ay)) and −xᵀM(Ax) = xᵀKx with K taken
//    before the stepping operator replaced it; a rigid translation is in its null space;
//  - the blocked kernel and PETSc's MatMult give the same product to rounding, and K is
//    kept only when asked for (an implicit integrator's Jacobian).
#include <petscmat.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "box_mesh_support.hpp"
#include "vibrotherm/wave/wave_operator.hpp"

namespace vibrotherm::testing {
namespace {

/// x with entries in [-1, 1) from a fixed seed.
PetscErrorCode RandomLike(Vec like, PetscInt seed, Vec* x) {
  PetscFunctionBeginUser;
  PetscRandom random;
  PetscCall(VecDuplicate(like, x));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &random));
  PetscCall(PetscRandomSetInterval(random, -1.0, 1.0));
  PetscCall(PetscRandomSetSeed(random, seed));
  PetscCall(PetscRandomSeed(random));
  PetscCall(VecSetRandom(*x, random));
  PetscCall(PetscRandomDestroy(&random));
  PetscFunctionReturn(0);
}

/// zᵀ (B y) for a linear map B applied as apply(y, By).
double DotAfter(Vec y, Vec z, const std::function<void(Vec, Vec)>& apply) {
  Vec By;
  VecDuplicate(y, &By);
  apply(y, By);
  PetscScalar dot;
  VecDot(By, z, &dot);
  VecDestroy(&By);
  return PetscRealPart(dot);
}

/// yᵀ M z (M the lumped mass as a vector).
double MassDot(Vec mass, Vec y, Vec z) {
  return DotAfter(y, z, [mass](Vec in, Vec out) { VecPointwiseMult(out, mass, in); });
}

/// xᵀ K x.
double Energy(Mat K, Vec x) {
  return DotAfter(x, x, [K](Vec in, Vec out) { MatMult(K, in, out); });
}

/// max_i Σ_j |K_ij| / M_i (Gershgorin: no eigenvalue of M⁻¹K lies above it), over all ranks.
double GershgorinBound(Mat K, Vec mass) {
  PetscInt rstart, rend;
  MatGetOwnershipRange(K, &rstart, &rend);
  const PetscScalar* m;
  VecGetArrayRead(mass, &m);
  double bound = 0.0;
  for (PetscInt row = rstart; row < rend; ++row) {
    PetscInt ncols;
    const PetscScalar* values;
    MatGetRow(K, row, &ncols, nullptr, &values);
    double sum = 0.0;
    for (PetscInt k = 0; k < ncols; ++k) sum += std::abs(PetscRealPart(values[k]));
    MatRestoreRow(K, row, &ncols, nullptr, &values);
    bound = std::max(bound, sum / PetscRealPart(m[row - rstart]));
  }
  VecRestoreArrayRead(mass, &m);
  MPI_Allreduce(MPI_IN_PLACE, &bound, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return bound;
}

class WaveOperatorAlone : public ::testing::TestWithParam<BoxCase> {
 protected:
  void SetUp() override {
    ASSERT_EQ(BoxMesh(GetParam(), &dm_), 0);
    ASSERT_EQ(op_.Setup(dm_, material_, GetParam().degree), 0);
  }
  void TearDown() override { DMDestroy(&dm_); }
  DM dm_ = nullptr;
  wave::ElasticMaterial material_;
  wave::WaveOperator op_;
};

TEST_P(WaveOperatorAlone, DimensionAndDofsAreTheMeshes) {
  const BoxCase c = GetParam();
  EXPECT_EQ(op_.space().dim(), c.dim);
  EXPECT_EQ(static_cast<int>(op_.space().components()), c.dim);  // one displacement component per dimension
  PetscInt n;
  ASSERT_EQ(VecGetSize(op_.mass(), &n), 0);
  EXPECT_EQ(op_.dofs(), n);
  std::vector<double> x;
  ASSERT_EQ(op_.space().NodePositions(&x), 0);
  PetscInt local;
  ASSERT_EQ(VecGetLocalSize(op_.mass(), &local), 0);
  EXPECT_LE(local, static_cast<PetscInt>(x.size()));  // this rank's nodes, D components each, owned ones
}

TEST_P(WaveOperatorAlone, LargestFrequencyIsTheTopOfTheSpectrum) {
  double omega;
  ASSERT_EQ(op_.LargestFrequency(&omega), 0);
  const double omega2 = omega * omega;
  // Power iteration on M⁻¹K: its Rayleigh quotients rise towards ω_max² from below.
  Vec x, Kx;
  ASSERT_EQ(RandomLike(op_.mass(), 3, &x), 0);
  VecDuplicate(x, &Kx);
  double quotient = 0.0;
  for (int k = 0; k < 200; ++k) {
    quotient = Energy(op_.stiffness(), x) / MassDot(op_.mass(), x, x);
    EXPECT_LE(quotient, omega2 * (1.0 + 1e-8)) << "iteration " << k;
    MatMult(op_.stiffness(), x, Kx);
    VecPointwiseMult(x, Kx, op_.inverse_mass());
    PetscReal norm;
    VecNorm(x, NORM_INFINITY, &norm);
    VecScale(x, 1.0 / norm);
  }
  EXPECT_GT(quotient, 0.9 * omega2);  // a wrong ω_max by 0.85 in ω² fails the bound above, on all 8 meshes
  EXPECT_LE(omega2, GershgorinBound(op_.stiffness(), op_.mass()) * (1.0 + 1e-8));
  VecDestroy(&x);
  VecDestroy(&Kx);
}

TEST_P(WaveOperatorAlone, SteppingIsMinusMassInverseStiffness) {
  Vec x, y, Ax, Ay;
  ASSERT_EQ(RandomLike(op_.mass(), 11, &x), 0);
  ASSERT_EQ(RandomLike(op_.mass(), 13, &y), 0);
  const double xKx = Energy(op_.stiffness(), x);
  ASSERT_EQ(op_.MakeStepping(false, wave::StiffnessKernel::kPetsc), 0);
  EXPECT_EQ(op_.stiffness(), nullptr);  // replaced in place, not kept
  VecDuplicate(x, &Ax);
  VecDuplicate(x, &Ay);
  ASSERT_EQ(op_.Apply(x, Ax), 0);
  ASSERT_EQ(op_.Apply(y, Ay), 0);
  const double yMAx = MassDot(op_.mass(), y, Ax), xMAy = MassDot(op_.mass(), x, Ay);
  EXPECT_NEAR(yMAx, xMAy, 1e-11 * std::abs(xKx));
  EXPECT_NEAR(-MassDot(op_.mass(), x, Ax), xKx, 1e-11 * std::abs(xKx));
  // A rigid translation along x: no force.
  VecDestroy(&x);
  const int D = op_.space().dim();
  ASSERT_EQ(NodalField(op_.space(), [D](const double*, double* u) { for (int k = 0; k < D; ++k) u[k] = k == 0; }, &x), 0);
  ASSERT_EQ(op_.Apply(x, Ax), 0);
  PetscReal force, scale;
  VecNorm(Ax, NORM_INFINITY, &force);
  MatNorm(op_.stepping(), NORM_INFINITY, &scale);
  EXPECT_LT(force, 1e-12 * scale);
  for (Vec* v : {&x, &y, &Ax, &Ay}) VecDestroy(v);
}

TEST_P(WaveOperatorAlone, BlockedKernelIsMatMultAndKIsKeptWhenAsked) {
  wave::WaveOperator petsc;
  ASSERT_EQ(petsc.Setup(dm_, material_, GetParam().degree), 0);
  ASSERT_EQ(petsc.MakeStepping(true, wave::StiffnessKernel::kPetsc), 0);
  EXPECT_NE(petsc.stiffness(), nullptr);  // kept for a Jacobian
  ASSERT_EQ(op_.MakeStepping(false, wave::StiffnessKernel::kBlocked), 0);
  Vec x, a, b;
  ASSERT_EQ(RandomLike(op_.mass(), 19, &x), 0);
  VecDuplicate(x, &a);
  VecDuplicate(x, &b);
  ASSERT_EQ(op_.Apply(x, a), 0);
  ASSERT_EQ(petsc.Apply(x, b), 0);
  PetscReal scale, difference;
  MatNorm(petsc.stepping(), NORM_INFINITY, &scale);
  VecAXPY(a, -1.0, b);
  VecNorm(a, NORM_INFINITY, &difference);
  EXPECT_LT(difference, 1e-13 * scale);
  for (Vec* v : {&x, &a, &b}) VecDestroy(v);
}

INSTANTIATE_TEST_SUITE_P(BoxMeshes, WaveOperatorAlone, ::testing::ValuesIn(AllBoxCases()), BoxCaseName);

}  // namespace
}  // namespace vibrotherm::testing

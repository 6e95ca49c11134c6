// Requirement: the 2×2-block kernel (-wave_kernel blocked) is the stepping
// operator A = −M⁻¹K of PETSc's MatMult to rounding, on the paper's wave mesh
// (Q2 quads, split crack), serial and on 2 ranks (ghost columns); its AVX2 and
// portable paths agree bit for bit; it follows A when A's values change after
// setup; and a whole run of steps with it stays on the MatMult run. The 3×3-block
// kernel (3D) is MatMult to rounding on a distributed Q2 hex box, both paths.
#include <petscmat.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vibrotherm/wave/elastic_operator.hpp"
#include "wave_test_support.hpp"

namespace vibrotherm::testing {
namespace {

std::string PaperOptions(const std::string& extra = "") {
  return std::string("-options_file ") + VIBROTHERM_SOURCE_DIR + "/options/paper.opts " + extra;
}

/// x with entries in [-1, 1) from a fixed seed (the same on every run and rank count).
PetscErrorCode RandomVector(Mat A, Vec* x) {
  PetscFunctionBeginUser;
  PetscRandom random;
  PetscCall(MatCreateVecs(A, x, nullptr));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &random));
  PetscCall(PetscRandomSetInterval(random, -1.0, 1.0));
  PetscCall(PetscRandomSetSeed(random, 17));
  PetscCall(PetscRandomSeed(random));
  PetscCall(VecSetRandom(*x, random));
  PetscCall(PetscRandomDestroy(&random));
  PetscFunctionReturn(0);
}

/// max |a − b| over all ranks.
double MaxDifference(Vec a, Vec b) {
  Vec d;
  VecDuplicate(a, &d);
  VecWAXPY(d, -1.0, b, a);
  PetscReal norm;
  VecNorm(d, NORM_INFINITY, &norm);
  VecDestroy(&d);
  return norm;
}

/// Rounding scale of y = A x: ‖A‖∞ ‖x‖∞ (sums of about 20 products per row).
double Scale(Mat A, Vec x) {
  PetscReal a, xn;
  MatNorm(A, NORM_INFINITY, &a);
  VecNorm(x, NORM_INFINITY, &xn);
  return a * xn;
}

TEST(BlockKernel, EqualsMatMultOnThePaperMesh) {
  ScopedWave w(PaperOptions());
  ASSERT_EQ(w.status, 0);
  Mat A = w.solver.op().stepping();
  Vec x, y_petsc, y_blocked, y_portable;
  ASSERT_EQ(RandomVector(A, &x), 0);
  VecDuplicate(x, &y_petsc);
  VecDuplicate(x, &y_blocked);
  VecDuplicate(x, &y_portable);
  ASSERT_EQ(MatMult(A, x, y_petsc), 0);
  wave::BlockKernel blocked, portable;
  ASSERT_EQ(blocked.Setup(A), 0);
  ASSERT_EQ(portable.Setup(A, false), 0);
  EXPECT_FALSE(portable.wide());
  ASSERT_EQ(blocked.Apply(x, y_blocked), 0);
  ASSERT_EQ(portable.Apply(x, y_portable), 0);
  const double scale = Scale(A, x);
  EXPECT_LT(MaxDifference(y_blocked, y_petsc), 1e-14 * scale);
  EXPECT_EQ(MaxDifference(y_blocked, y_portable), 0.0) << "the AVX2 and portable paths differ";
  PetscReal norm;
  VecNorm(y_petsc, NORM_INFINITY, &norm);
  EXPECT_GT(norm, 1e-3 * scale);  // a real product, not two zero vectors
  for (Vec* v : {&x, &y_petsc, &y_blocked, &y_portable}) VecDestroy(v);
}

TEST(BlockKernel, FollowsTheMatrixWhenItsValuesChange) {
  ScopedWave w(PaperOptions());
  ASSERT_EQ(w.status, 0);
  Mat A;
  ASSERT_EQ(MatDuplicate(w.solver.op().stepping(), MAT_COPY_VALUES, &A), 0);
  wave::BlockKernel kernel;
  ASSERT_EQ(kernel.Setup(A), 0);
  Vec x, y_petsc, y_blocked;
  ASSERT_EQ(RandomVector(A, &x), 0);
  VecDuplicate(x, &y_petsc);
  VecDuplicate(x, &y_blocked);
  ASSERT_EQ(kernel.Apply(x, y_blocked), 0);
  Vec scaling;
  VecDuplicate(x, &scaling);
  VecCopy(x, scaling);
  VecAbs(scaling);
  VecShift(scaling, 0.5);
  ASSERT_EQ(MatDiagonalScale(A, scaling, nullptr), 0);  // after the kernel copied A
  ASSERT_EQ(MatMult(A, x, y_petsc), 0);
  ASSERT_EQ(kernel.Apply(x, y_blocked), 0);
  EXPECT_LT(MaxDifference(y_blocked, y_petsc), 1e-14 * Scale(A, x));
  for (Vec* v : {&x, &y_petsc, &y_blocked, &scaling}) VecDestroy(v);
  MatDestroy(&A);
}

/// u after `steps` wave steps of the paper scene with -wave_kernel `kernel`, gathered.
std::vector<double> DisplacementAfter(const char* kernel, PetscInt steps) {
  ScopedWave w(PaperOptions(std::string("-wave_kernel ") + kernel));
  if (w.status || w.solver.AdvanceSteps(steps)) return {};
  Vec u, v;
  w.solver.GetFields(&u, &v);
  const PetscScalar* a;
  PetscInt n;
  VecGetLocalSize(u, &n);
  VecGetArrayRead(u, &a);
  std::vector<double> mine(a, a + n);
  VecRestoreArrayRead(u, &a);
  w.solver.RestoreFields(&u, &v);
  return AllGather(mine);
}

TEST(BlockKernel, StepsStayOnTheMatMultSteps) {
  const std::vector<double> petsc = DisplacementAfter("petsc", 400), blocked = DisplacementAfter("blocked", 400);
  ASSERT_EQ(petsc.size(), blocked.size());
  ASSERT_FALSE(petsc.empty());
  double largest = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < petsc.size(); ++i) {
    largest = std::max(largest, std::abs(petsc[i]));
    difference = std::max(difference, std::abs(petsc[i] - blocked[i]));
  }
  EXPECT_GT(largest, 0.0);  // the source has moved the specimen
  EXPECT_LT(difference, 1e-11 * largest);
}

TEST(BlockKernel, ThreeByThreeEqualsMatMultOnADistributedHexBox) {
  const PetscInt faces[3] = {5, 4, 3};
  DM dm, distributed = nullptr;
  ASSERT_EQ(DMPlexCreateBoxMesh(PETSC_COMM_WORLD, 3, PETSC_FALSE, faces, nullptr, nullptr, nullptr, PETSC_TRUE, &dm), 0);
  ASSERT_EQ(DMPlexDistribute(dm, 0, nullptr, &distributed), 0);
  if (distributed) {
    DMDestroy(&dm);
    dm = distributed;
  }
  fe::LagrangeSpace space;
  ASSERT_EQ(space.Setup(dm, 2, 3), 0);
  Mat K;
  Vec mass, x, y_petsc, y_blocked;
  ASSERT_EQ(wave::AssembleElasticOperators(space, wave::ElasticMaterial{}, &K, &mass), 0);
  ASSERT_EQ(RandomVector(K, &x), 0);
  MatCreateVecs(K, nullptr, &y_petsc);
  VecDuplicate(y_petsc, &y_blocked);
  MatMult(K, x, y_petsc);
  for (bool wide : {false, true}) {
    wave::BlockKernel kernel;
    ASSERT_EQ(kernel.Setup(K, wide), 0);
    ASSERT_EQ(kernel.Apply(x, y_blocked), 0);
    EXPECT_LT(MaxDifference(y_blocked, y_petsc), 1e-14 * Scale(K, x)) << "wide " << kernel.wide();
  }
  VecDestroy(&x);
  VecDestroy(&y_petsc);
  VecDestroy(&y_blocked);
  VecDestroy(&mass);
  MatDestroy(&K);
  DMDestroy(&dm);
}

TEST(BlockKernel, RefusesMatricesItDoesNotHandle) {
  Mat A;
  MatCreateAIJ(PETSC_COMM_WORLD, 4, 4, PETSC_DETERMINE, PETSC_DETERMINE, 1, nullptr, 0, nullptr, &A);
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  wave::BlockKernel kernel;
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  EXPECT_NE(kernel.Setup(A), 0);
  PetscPopErrorHandler();
  MatDestroy(&A);
}

}  // namespace
}  // namespace vibrotherm::testing

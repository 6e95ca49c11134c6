// Requirement (issue 40, the cooling phase): the heat's linear solvers are set up once per
// step length and reused by every step of that length (heat/rung_solvers.hpp):
//  - RungSolvers gives the same solver for a shift within a relative 1e-10 (equal steps
//    differ in their last bits), a new one for another shift, keeps the last kCapacity and
//    drops the least recently used; each solves K + shift·M;
//  - a free phase whose steps are clipped to camera-like windows (step lengths alternating,
//    the step ladder growing between them) on a 3D box large enough to iterate (CG with
//    Jacobi on the short steps, BoomerAMG on the long ones) sets up exactly as many solvers
//    as an LRU cache of kCapacity step lengths misses (counted here from the steps taken),
//    fewer than the changes of step length (what one solver per TS set up before), and gives
//    the temperatures of the same run with an exact factorisation in every rung (CG +
//    PCREDUNDANT's LU: one iteration) within 1e-6 of the peak rise (CG's relative tolerance
//    on each step's update is 1e-8).
#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

#include "graded_box_support.hpp"
#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/heat/rung_solvers.hpp"

namespace vibrotherm::testing {
namespace {

/// K: the 1D Laplacian (2, −1) of n rows, M = identity, on PETSC_COMM_SELF.
PetscErrorCode Laplacian(PetscInt n, Mat* K, Mat* M) {
  PetscFunctionBeginUser;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 3, nullptr, K));
  for (PetscInt i = 0; i < n; ++i) {
    PetscCall(MatSetValue(*K, i, i, 2.0, INSERT_VALUES));
    if (i > 0) PetscCall(MatSetValue(*K, i, i - 1, -1.0, INSERT_VALUES));
    if (i + 1 < n) PetscCall(MatSetValue(*K, i, i + 1, -1.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatDuplicate(*K, MAT_DO_NOT_COPY_VALUES, M));
  PetscCall(MatShift(*M, 1.0));
  PetscFunctionReturn(0);
}

TEST(RungSolvers, OneSolverPerShiftLeastRecentlyUsedDropped) {
  Mat K, M;
  ASSERT_EQ(Laplacian(20, &K, &M), 0);
  heat::RungSolvers rungs;
  ASSERT_EQ(rungs.Setup(
      K,
      [&](double shift, Mat J) {
        PetscFunctionBeginUser;
        PetscCall(MatCopy(K, J, SAME_NONZERO_PATTERN));
        PetscCall(MatAXPY(J, shift, M, SAME_NONZERO_PATTERN));
        PetscFunctionReturn(0);
      },
      [](double, KSP ksp) {
        PetscFunctionBeginUser;
        PetscCall(KSPSetType(ksp, KSPPREONLY));
        PC pc;
        PetscCall(KSPGetPC(ksp, &pc));
        PetscCall(PCSetType(pc, PCLU));
        PetscFunctionReturn(0);
      }),
            0);
  KSP a, b, c;
  ASSERT_EQ(rungs.Get(1.0, &a), 0);
  ASSERT_EQ(rungs.Get(1.0 * (1 + 1e-12), &b), 0);
  EXPECT_EQ(a, b) << "a shift within 1e-10 reuses the solver";
  ASSERT_EQ(rungs.Get(1.0 * (1 + 1e-8), &c), 0);
  EXPECT_NE(a, c) << "a shift 1e-8 away gets its own";
  EXPECT_EQ(rungs.setups(), 2);
  // J x = b for x = 1: (K + shift M) 1 = shift, plus 1 at both ends.
  for (double shift : {3.0, 50.0}) {
    KSP ksp;
    ASSERT_EQ(rungs.Get(shift, &ksp), 0);
    Vec x, rhs;
    ASSERT_EQ(MatCreateVecs(K, &x, &rhs), 0);
    ASSERT_EQ(VecSet(rhs, shift), 0);
    ASSERT_EQ(VecSetValue(rhs, 0, shift + 1.0, INSERT_VALUES), 0);
    ASSERT_EQ(VecSetValue(rhs, 19, shift + 1.0, INSERT_VALUES), 0);
    ASSERT_EQ(VecAssemblyBegin(rhs), 0);
    ASSERT_EQ(VecAssemblyEnd(rhs), 0);
    ASSERT_EQ(KSPSolve(ksp, rhs, x), 0);
    ASSERT_EQ(VecShift(x, -1.0), 0);
    PetscReal error;
    ASSERT_EQ(VecNorm(x, NORM_INFINITY, &error), 0);
    EXPECT_LT(error, 1e-12) << "shift " << shift;
    VecDestroy(&x);
    VecDestroy(&rhs);
  }
  EXPECT_EQ(rungs.setups(), 4);  // kept: 1, 1 + 1e-8, 3, 50 (used in that order)
  ASSERT_EQ(rungs.Get(1.0, &b), 0);  // 1 is now the most recent; 1 + 1e-8 the least
  ASSERT_EQ(rungs.Get(7.0, &b), 0);  // a fifth: 1 + 1e-8 goes
  EXPECT_EQ(rungs.setups(), 5);
  ASSERT_EQ(rungs.Get(3.0, &b), 0);
  ASSERT_EQ(rungs.Get(1.0, &b), 0);
  EXPECT_EQ(rungs.setups(), 5) << "3 and 1 were kept";
  ASSERT_EQ(rungs.Get(1.0 * (1 + 1e-8), &b), 0);
  EXPECT_EQ(rungs.setups(), 6) << "1 + 1e-8 was dropped";
  MatDestroy(&K);
  MatDestroy(&M);
}

/// Step lengths an LRU cache of `capacity` step lengths (a relative 1e-10 apart) would not hold.
int LruMisses(const std::vector<double>& steps, std::size_t capacity) {
  std::deque<double> cache;  // most recent at the front
  int misses = 0;
  for (double h : steps) {
    auto hit = std::find_if(cache.begin(), cache.end(), [h](double c) { return std::abs(c - h) <= 1e-10 * h; });
    if (hit != cache.end()) {
      const double c = *hit;
      cache.erase(hit);
      cache.push_front(c);
      continue;
    }
    ++misses;
    cache.push_front(h);
    if (cache.size() > capacity) cache.pop_back();
  }
  return misses;
}

struct Cooling {
  std::vector<double> steps, rise;
  PetscInt setups = 0, dofs = 0;
};

/// A 3D box of 18³ graded cells, every face a sink, heated at its centre by 4 coupled steps,
/// then cooling freely to 0.3 on the ladder (4 steps a rung) with camera-like stops: windows
/// [0.1 + 0.02 k, 0.1 + 0.02 k + 0.005]. free_pc: -heat_free_pc_type (nullptr: the default).
PetscErrorCode Cool(const char* free_pc, Cooling* out) {
  PetscFunctionBeginUser;
  const std::vector<double> axis = MirroredAxis(GradedAxis(0.2, 1.0, 0.5, 9));
  DM dm;
  PetscCall(GradedBox(PETSC_COMM_WORLD, {axis, axis, axis}, false, [](const double*) { return true; }, &dm));
  PetscCall(PetscOptionsSetValue(nullptr, "-heat_free_ts_adapt_ladder_steps", "4"));
  // No cap on the step (another test of the suite, HeatLineSource, leaves one in the options).
  PetscCall(PetscOptionsSetValue(nullptr, "-heat_free_ts_adapt_dt_max", "1e300"));
  if (free_pc) PetscCall(PetscOptionsSetValue(nullptr, "-heat_free_pc_type", free_pc));
  {
    heat::HeatOptions options;
    options.material.density = options.material.capacity = options.material.conductivity = 1.0;
    heat::HeatSolver heat;
    PetscCall(heat.Setup(dm, options));
    heat::HeatProbes probes;
    PetscCall(probes.Locate(heat.space(), {0, 0, 0, 0.1, 0.05, 0, 0.3, 0.2, 0.1}));
    Vec Q;  // a point load at the centre: the heat basis there
    PetscCall(DMCreateGlobalVector(dm, &Q));
    PetscCall(probes.Functional(0, Q));
    PetscCall(heat.SetSourceLoad(Q));
    PetscCall(heat.AdvanceInSteps(4e-3, 4));
    PetscCall(VecSet(Q, 0.0));
    PetscCall(heat.SetSourceLoad(Q));
    PetscCall(VecDestroy(&Q));
    PetscCall(heat.UseFreeIntegrator());
    double t_prev = heat.time();
    heat.on_step = [&](const heat::HeatSolver& h) {
      out->steps.push_back(h.time() - t_prev);
      t_prev = h.time();
      return PetscErrorCode(0);
    };
    for (int k = 0; k <= 10; ++k)
      for (double stop : {0.1 + 0.02 * k, 0.105 + 0.02 * k}) PetscCall(heat.AdvanceTo(stop));
    PetscCall(heat.AdvanceTo(0.3));
    std::vector<double> T;
    PetscCall(probes.Temperatures(heat.rise(), heat.material().T0, &T));
    for (double t : T) out->rise.push_back(t - heat.material().T0);
    out->setups = heat.free_solver_setups();
    out->dofs = heat.dofs();
  }
  PetscCall(PetscOptionsClearValue(nullptr, "-heat_free_ts_adapt_ladder_steps"));
  PetscCall(PetscOptionsClearValue(nullptr, "-heat_free_ts_adapt_dt_max"));
  if (free_pc) PetscCall(PetscOptionsClearValue(nullptr, "-heat_free_pc_type"));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

TEST(RungSolvers, CoolingSetsUpOneSolverPerStepLengthSameTemperatures) {
  Cooling rungs, exact;
  ASSERT_EQ(Cool(nullptr, &rungs), 0);
  ASSERT_EQ(Cool("redundant", &exact), 0);
  ASSERT_GT(rungs.dofs, 5000) << "the box must be large enough for the iterative solvers";
  ASSERT_EQ(rungs.steps.size(), exact.steps.size());
  int changes = 1;
  for (std::size_t i = 1; i < rungs.steps.size(); ++i)
    changes += std::abs(rungs.steps[i] - rungs.steps[i - 1]) > 1e-10 * rungs.steps[i];
  const int misses = LruMisses(rungs.steps, heat::RungSolvers::kCapacity);
  EXPECT_EQ(rungs.setups, misses) << "one setup per step length the cache does not hold";
  EXPECT_LT(misses, changes - 10) << "the alternating windows reuse their solvers";
  EXPECT_EQ(exact.setups, misses);
  const double peak = std::max(std::abs(exact.rise[0]), 1e-300);
  for (std::size_t p = 0; p < exact.rise.size(); ++p)
    EXPECT_LE(std::abs(rungs.rise[p] - exact.rise[p]), 1e-6 * peak) << "probe " << p;
  EXPECT_GT(exact.rise[0], 0.0);
  PetscPrintf(PETSC_COMM_WORLD, "cooling: %zu steps, %d changes of length, %d setups; rise %.6g against %.6g\n",
              rungs.steps.size(), changes, static_cast<int>(rungs.setups), rungs.rise[0], exact.rise[0]);
}

}  // namespace
}  // namespace vibrotherm::testing

// Requirement: the free-diffusion step ladder (-heat_free_ts_adapt_type ladder)
// holds each step for its steps-per-rung, then grows it by the ratio; clips
// steps to hit each TSSolve's final time and -ts_adapt_dt_max without losing
// the rung, also across several TSSolve calls (the heat solver makes one per
// output segment) and when the first segment is shorter than the first rung;
// and (with Crank-Nicolson) converges at second order in the steps per rung on
// a decay y' = −λ y started where the step is λ-small, as after the waves (the
// closed form exp(−λ t) is the reference). A bad count is refused naming the
// option with the TS's prefix.
#include <gtest/gtest.h>
#include <petscts.h>

#include <cmath>
#include <string>
#include <vector>

#include "vibrotherm/heat/step_ladder.hpp"

namespace vibrotherm::testing {
namespace {

constexpr double kLambda = 50.0;

PetscErrorCode Decay(TS, PetscReal, Vec y, Vec ydot, Vec F, void*) {
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(F, kLambda, y, ydot));
  PetscFunctionReturn(0);
}

PetscErrorCode DecayJacobian(TS, PetscReal, Vec, Vec, PetscReal shift, Mat J, Mat, void*) {
  PetscFunctionBeginUser;
  PetscCall(MatSetValue(J, 0, 0, shift + kLambda, INSERT_VALUES));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// The accepted steps, once each (a monitor would also see each TSSolve's start).
PetscErrorCode RecordStep(TS ts) {
  PetscFunctionBeginUser;
  PetscReal t, t_prev;
  PetscCall(TSGetTime(ts, &t));
  PetscCall(TSGetPrevTime(ts, &t_prev));
  void* steps;
  PetscCall(TSGetApplicationContext(ts, &steps));
  static_cast<std::vector<double>*>(steps)->push_back(t - t_prev);
  PetscFunctionReturn(0);
}

struct LadderRun {
  std::vector<double> steps;
  double y_end = 0.0;
};

/// y(0) = 1 to each of `stops` in turn (one TSSolve each), first step h0 (also
/// given to StepLadderStart when `start`), under the -ts_adapt_* options.
LadderRun RunDecay(const char* options, double h0, const std::vector<double>& stops, bool start = false) {
  LadderRun run;
  PetscOptions own;  // the run's own database: the suite's options stay as they are
  EXPECT_EQ(PetscOptionsCreate(&own), 0);
  EXPECT_EQ(PetscOptionsInsertString(own, options), 0);
  EXPECT_EQ(heat::RegisterStepLadder(), 0);
  Vec y;
  Mat J;
  TS ts;
  EXPECT_EQ(VecCreateSeq(PETSC_COMM_SELF, 1, &y), 0);
  EXPECT_EQ(VecSet(y, 1.0), 0);
  EXPECT_EQ(MatCreateSeqDense(PETSC_COMM_SELF, 1, 1, nullptr, &J), 0);
  EXPECT_EQ(TSCreate(PETSC_COMM_SELF, &ts), 0);
  EXPECT_EQ(PetscObjectSetOptions((PetscObject)ts, own), 0);
  EXPECT_EQ(TSSetProblemType(ts, TS_LINEAR), 0);
  EXPECT_EQ(TSSetType(ts, TSCN), 0);
  EXPECT_EQ(TSSetIFunction(ts, nullptr, Decay, nullptr), 0);
  EXPECT_EQ(TSSetIJacobian(ts, J, J, DecayJacobian, nullptr), 0);
  TSAdapt adapt;
  EXPECT_EQ(TSGetAdapt(ts, &adapt), 0);
  EXPECT_EQ(TSAdaptSetType(adapt, heat::kStepLadderAdapt), 0);
  EXPECT_EQ(TSSetTimeStep(ts, h0), 0);
  EXPECT_EQ(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_MATCHSTEP), 0);
  EXPECT_EQ(TSSetApplicationContext(ts, &run.steps), 0);
  EXPECT_EQ(TSSetPostStep(ts, RecordStep), 0);
  EXPECT_EQ(TSSetFromOptions(ts), 0);
  if (start) EXPECT_EQ(heat::StepLadderStart(adapt, h0), 0);
  for (double stop : stops) {
    EXPECT_EQ(TSSetMaxTime(ts, stop), 0);
    EXPECT_EQ(TSSolve(ts, y), 0);
    PetscReal t;
    EXPECT_EQ(TSGetTime(ts, &t), 0);
    EXPECT_NEAR(t, stop, 1e-12 * stop);
  }
  const PetscScalar* v;
  EXPECT_EQ(VecGetArrayRead(y, &v), 0);
  run.y_end = PetscRealPart(v[0]);
  EXPECT_EQ(VecRestoreArrayRead(y, &v), 0);
  EXPECT_EQ(TSDestroy(&ts), 0);
  EXPECT_EQ(MatDestroy(&J), 0);
  EXPECT_EQ(VecDestroy(&y), 0);
  EXPECT_EQ(PetscOptionsDestroy(&own), 0);
  return run;
}

std::size_t DistinctSteps(const std::vector<double>& steps) {
  std::vector<double> distinct;
  for (double h : steps)
    if (distinct.empty() || std::abs(h - distinct.back()) > 1e-12 * h) distinct.push_back(h);
  return distinct.size();
}

TEST(StepLadder, HoldsEachRungThenGrowsByTheRatio) {
  const LadderRun run = RunDecay("-ts_adapt_ladder_steps 3 -ts_adapt_ladder_ratio 2", 1e-4, {1.0});
  ASSERT_GT(run.steps.size(), 20u);
  // All but the last three: matchstep may split the stretch before t_end into halves.
  for (std::size_t k = 0; k + 3 < run.steps.size(); ++k)
    EXPECT_NEAR(run.steps[k], 1e-4 * std::pow(2.0, static_cast<double>(k / 3)), 1e-9 * run.steps[k]) << "step " << k;
  // Distinct steps (one factorisation each in the heat solver): a rung per 3 steps.
  EXPECT_LE(DistinctSteps(run.steps), run.steps.size() / 3 + 2);
}

TEST(StepLadder, KeepsTheRungAcrossSolvesAndShortFirstSegments) {
  // The first segment (1e-9) is far shorter than the first rung (1e-4), as when an
  // output time falls just after the waves stop; then four more segments.
  const std::vector<double> stops = {1e-9, 0.01, 0.03, 0.1, 0.5};
  const LadderRun run = RunDecay("-ts_adapt_ladder_steps 4", 1e-4, stops, true);
  const LadderRun whole = RunDecay("-ts_adapt_ladder_steps 4", 1e-4, {0.5});
  ASSERT_FALSE(run.steps.empty());
  EXPECT_NEAR(run.steps.front(), 1e-9, 1e-15);
  // The ladder went on as in one solve: the same rungs, a few extra steps at each stop.
  EXPECT_LE(run.steps.size(), whole.steps.size() + 3 * stops.size());
  EXPECT_LE(DistinctSteps(run.steps), DistinctSteps(whole.steps) + 3 * stops.size());
  double largest = 0.0;
  for (double h : run.steps) largest = std::max(largest, h);
  for (double h : whole.steps) EXPECT_LE(h, 2.0 * largest * (1 + 1e-12));
}

TEST(StepLadder, ClipsToTheMaximumStepAndKeepsIt) {
  const LadderRun run = RunDecay("-ts_adapt_ladder_steps 2 -ts_adapt_dt_max 1e-2", 1e-3, {0.2});
  ASSERT_FALSE(run.steps.empty());
  for (double h : run.steps) EXPECT_LE(h, 1e-2 * (1 + 1e-12));
  EXPECT_NEAR(run.steps[run.steps.size() / 2], 1e-2, 1e-12);  // held at the cap, not reset
}

TEST(StepLadder, CrankNicolsonConvergesAtSecondOrderInStepsPerRung) {
  // From h0 λ = 1e-3 to t = 0.1 (y = e^-5; the paper's crack centre falls ~e^-5 from 1 ms to 1 s):
  // the errors fall ~4x per doubling of the steps per rung.
  std::vector<double> errors;
  for (const char* m : {"-ts_adapt_ladder_steps 4", "-ts_adapt_ladder_steps 8", "-ts_adapt_ladder_steps 16"}) {
    const LadderRun run = RunDecay(m, 2e-5, {0.1});
    errors.push_back(std::abs(run.y_end - std::exp(-kLambda * 0.1)) / std::exp(-kLambda * 0.1));
  }
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    const double ratio = errors[k] / errors[k + 1];
    RecordProperty("ratio" + std::to_string(k), std::to_string(ratio));
    EXPECT_GT(ratio, 3.0) << "errors " << errors[k] << " -> " << errors[k + 1];
  }
  EXPECT_LT(errors.back(), 1e-2);
}

PetscErrorCode KeepFirstMessage(MPI_Comm, int, const char*, const char*, PetscErrorCode n, PetscErrorType p,
                                const char* message, void* ctx) {
  auto* kept = static_cast<std::string*>(ctx);
  if (p == PETSC_ERROR_INITIAL && kept->empty()) *kept = message;
  return n;
}

TEST(StepLadder, RefusesAStepCountBelowOneNamingTheOption) {
  PetscOptions own;
  ASSERT_EQ(PetscOptionsCreate(&own), 0);
  ASSERT_EQ(PetscOptionsInsertString(own, "-heat_free_ts_adapt_ladder_steps 0"), 0);
  ASSERT_EQ(heat::RegisterStepLadder(), 0);
  TS ts;
  ASSERT_EQ(TSCreate(PETSC_COMM_SELF, &ts), 0);
  ASSERT_EQ(PetscObjectSetOptions((PetscObject)ts, own), 0);
  ASSERT_EQ(TSSetOptionsPrefix(ts, "heat_free_"), 0);
  TSAdapt adapt;
  ASSERT_EQ(TSGetAdapt(ts, &adapt), 0);
  ASSERT_EQ(TSAdaptSetType(adapt, heat::kStepLadderAdapt), 0);
  std::string message;
  ASSERT_EQ(PetscPushErrorHandler(KeepFirstMessage, &message), 0);
  EXPECT_EQ(TSSetFromOptions(ts), PETSC_ERR_USER_INPUT);
  ASSERT_EQ(PetscPopErrorHandler(), 0);
  EXPECT_NE(message.find("-heat_free_ts_adapt_ladder_steps must be >= 1"), std::string::npos) << message;
  ASSERT_EQ(TSDestroy(&ts), 0);
  ASSERT_EQ(PetscOptionsDestroy(&own), 0);
}

}  // namespace
}  // namespace vibrotherm::testing

// Requirement (issue 27): the wave phase's progress never shows more steps taken
// than expected ("step 21761/2432 (100 %)" after the contact shrank the step):
// the count is the steps taken plus those left at the current step, and once the
// waves outlast their expected end the line says so instead of a count.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "vibrotherm/io/progress.hpp"

namespace vibrotherm::io {
namespace {

TEST(Progress, CountsTheStepsLeftAtTheCurrentStep) {
  // Started at dt = 1e-8 to t_end = 2.432e-5 (2432 steps); the contact shrank the step
  // tenfold at 1e-5 s: 1000 + 14320 steps.
  EXPECT_EQ(StepCount(1000, 1.00005e-5, 2.432e-5, 1e-8), "step 1000/2432");  // 1431.5 left
  EXPECT_EQ(StepCount(1000, 1.00005e-5, 2.432e-5, 1e-9), "step 1000/15320");  // 14319.5 left
  EXPECT_EQ(StepCount(21761, 2.29995e-5, 2.432e-5, 1e-9), "step 21761/23082");  // 1320.5 left
}

TEST(Progress, PastTheExpectedEndShowsNoCount) {
  const std::string count = StepCount(21761, 3e-5, 2.432e-5, 1e-9);
  EXPECT_EQ(count.find('/'), std::string::npos) << count;
  EXPECT_NE(count.find("past the expected end"), std::string::npos) << count;
}

// Issue 40: a heat phase without waves (-physics heat) printed "the waves are not quiet
// yet" at its end: the step count of the wave phase, estimated from the steps taken.
TEST(Progress, AHeatPhaseNeverCountsWaveSteps) {
  Progress heat;
  heat.Start(MPI_COMM_WORLD, "heat", 1e-8, 1e-2, 0.0, true);
  double t = 1e-8;
  for (long long step = 1; step <= 320; ++step) {
    t = std::min(1e-2, t * 1.05);
    ASSERT_EQ(heat.Update(t, step), 0);
  }
  for (double at : {1e-4, 1e-2}) {
    const std::string line = heat.Line(at, 320, 10.0);
    EXPECT_EQ(line.find("waves"), std::string::npos) << line;
    EXPECT_EQ(line.find('/'), std::string::npos) << line;
    EXPECT_NE(line.find("in log time"), std::string::npos) << line;
  }
  Progress waves;  // the wave phase keeps its count
  waves.Start(MPI_COMM_WORLD, "wave", 0.0, 2e-5, 1e-8, false);
  ASSERT_EQ(waves.Update(1e-5, 1000), 0);
  EXPECT_NE(waves.Line(1e-5, 1000, 1.0).find("step 1000/200"), std::string::npos) << waves.Line(1e-5, 1000, 1.0);
  EXPECT_NE(waves.Line(3e-5, 3000, 1.0).find("not quiet yet"), std::string::npos);
}

}  // namespace
}  // namespace vibrotherm::io

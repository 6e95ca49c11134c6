// Requirement (issue 27): the wave phase's progress never shows more steps taken
// than expected ("step 21761/2432 (100 %)" after the contact shrank the step):
// the count is the steps taken plus those left at the current step, and once the
// waves outlast their expected end the line says so instead of a count.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace vibrotherm::io

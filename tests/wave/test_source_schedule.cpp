// Requirement (issue 24): a piecewise-constant amplitude schedule (-source_schedule) is a smooth
// source: g, dg/dt, d²g/dt² agree with finite differences everywhere (the displacement source
// prescribes all three); the amplitude holds each level between blends; the steady stretches
// (constant amplitude, no ramp) are where the source is periodic.
#include <gtest/gtest.h>

#include <cmath>

#include "vibrotherm/wave/excitation.hpp"

namespace vibrotherm::wave {
namespace {

SourceTimeFunction Scheduled() {
  SourceTimeFunction f;
  f.amplitude = 1e-7;
  f.frequency = 1e5;
  f.duration = 1e-3;
  f.ramp_cycles = 3.0;
  f.schedule = {{2e-4, 3e-7}, {5e-4, 0.5e-7}};
  return f;
}

TEST(SourceSchedule, DerivativesAgreeWithFiniteDifferences) {
  const SourceTimeFunction f = Scheduled();
  const double h = 1e-10;
  double worst_d = 0.0, worst_dd = 0.0;
  for (double t = 1e-6; t < 1e-3 - 1e-6; t += 1.37e-6) {
    double g[3], dg[3], ddg[3];
    for (int k = 0; k < 3; ++k) f.evaluate(t + (k - 1) * h, &g[k], &dg[k], &ddg[k]);
    worst_d = std::max(worst_d, std::abs((g[2] - g[0]) / (2 * h) - dg[1]));
    worst_dd = std::max(worst_dd, std::abs((dg[2] - dg[0]) / (2 * h) - ddg[1]));
  }
  const double w = 2 * M_PI * 1e5, amax = 3e-7;
  EXPECT_LT(worst_d, 1e-6 * amax * w);
  EXPECT_LT(worst_dd, 1e-5 * amax * w * w);
}

TEST(SourceSchedule, LevelsAndSteadyStretches) {
  const SourceTimeFunction f = Scheduled();
  auto peak = [&](double t0) {  // the carrier's peak a quarter period after a period start
    double g, dg, ddg;
    f.evaluate(t0 + 0.25e-5, &g, &dg, &ddg);
    return g;
  };
  EXPECT_NEAR(peak(1e-4), 1e-7, 1e-20);
  EXPECT_NEAR(peak(3e-4), 3e-7, 1e-20);
  EXPECT_NEAR(peak(8e-4), 0.5e-7, 1e-20);
  double start, end;
  EXPECT_TRUE(f.steady_stretch(1e-4, &start, &end));
  EXPECT_DOUBLE_EQ(start, 3e-5);
  EXPECT_DOUBLE_EQ(end, 2e-4);
  EXPECT_TRUE(f.steady_stretch(3e-4, &start, &end));
  EXPECT_DOUBLE_EQ(start, 2e-4 + 3e-5);
  EXPECT_DOUBLE_EQ(end, 5e-4);
  EXPECT_TRUE(f.steady_stretch(9e-4, &start, &end));
  EXPECT_DOUBLE_EQ(end, 1e-3 - 3e-5);
  EXPECT_FALSE(f.steady_stretch(2.1e-4, &start, &end));  // in a blend
  EXPECT_FALSE(f.steady_stretch(1e-5, &start, &end));    // in the switch-on
}

}  // namespace
}  // namespace vibrotherm::wave

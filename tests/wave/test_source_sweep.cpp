// Requirement (issue 38): -source_sweep F1,F2 is a linear chirp over the source duration: the
// instantaneous frequency runs from F1 to F2, the cycles counted are its integral (and
// time_of_cycle their inverse), g, dg/dt and d²g/dt² agree with finite differences (the
// displacement source prescribes all three), and a sweep has no steady stretch (it never repeats).
#include <gtest/gtest.h>

#include <cmath>

#include "vibrotherm/wave/excitation.hpp"

namespace vibrotherm::wave {
namespace {

SourceTimeFunction Sweep(double f1, double f2) {
  SourceTimeFunction f;
  f.amplitude = 1e-7;
  f.duration = 2e-3;
  f.ramp_cycles = 3.0;
  f.sweep_from = f1;
  f.sweep_to = f2;
  f.frequency = std::max(f1, f2);
  return f;
}

TEST(SourceSweep, CyclesAreTheIntegralOfTheInstantaneousFrequency) {
  for (const auto& [f1, f2] : {std::pair{2e4, 6e4}, std::pair{6e4, 2e4}}) {
    const SourceTimeFunction f = Sweep(f1, f2);
    EXPECT_DOUBLE_EQ(f.frequency_at(0.0), f1);
    EXPECT_DOUBLE_EQ(f.frequency_at(f.duration), f2);
    // Simpson's rule of f(t) over [0, T] is exact for a linear f.
    const double T = f.duration, integral = T / 6 * (f1 + 4 * f.frequency_at(T / 2) + f2);
    EXPECT_NEAR(f.cycles(T), integral, 1e-9 * integral);
    for (double n : {0.5, 3.0, 17.25, 79.0}) EXPECT_NEAR(f.cycles(f.time_of_cycle(n)), n, 1e-9 * n);
    double start, end;
    EXPECT_FALSE(f.steady_stretch(T / 2, &start, &end));
  }
}

TEST(SourceSweep, DerivativesAgreeWithFiniteDifferences) {
  const SourceTimeFunction f = Sweep(2e4, 6e4);
  const double h = 1e-10;
  double worst_d = 0.0, worst_dd = 0.0;
  for (double t = 1e-6; t < f.duration - 1e-6; t += 1.37e-6) {
    double g[3], dg[3], ddg[3];
    for (int k = 0; k < 3; ++k) f.evaluate(t + (k - 1) * h, &g[k], &dg[k], &ddg[k]);
    worst_d = std::max(worst_d, std::abs((g[2] - g[0]) / (2 * h) - dg[1]));
    worst_dd = std::max(worst_dd, std::abs((dg[2] - dg[0]) / (2 * h) - ddg[1]));
  }
  const double w = 2 * M_PI * 6e4;
  EXPECT_LT(worst_d, 1e-6 * 1e-7 * w);
  EXPECT_LT(worst_dd, 1e-5 * 1e-7 * w * w);
}

TEST(SourceSweep, ZeroCrossingsFollowTheCycles) {
  // sin(2π c(t)) changes sign where c(t) is a half integer: at time_of_cycle(k/2).
  const SourceTimeFunction f = Sweep(2e4, 6e4);
  for (double n : {10.0, 10.5, 40.0, 60.5}) {
    const double t = f.time_of_cycle(n), eps = 1e-3 / f.frequency_at(t);
    double before, after, d, dd;
    f.evaluate(t - eps, &before, &d, &dd);
    f.evaluate(t + eps, &after, &d, &dd);
    EXPECT_LT(before * after, 0.0) << n;
  }
}

}  // namespace
}  // namespace vibrotherm::wave

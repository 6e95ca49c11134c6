// Requirement (issue 38: the LDR study's runs that never settled): -periodic_mode mean judges the
// heat per period as samples of a stationary process. The criterion is the last window's
// standard error over its mean, or a trend between the two last windows; its window doubles
// when a crack's heat per period scatters too much to know its mean within a window.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "vibrotherm/coupling/continuation/periodic_mean.hpp"

namespace vibrotherm::coupling {
namespace {

TEST(PeriodicMean, AlternatingValuesGiveTheirClosedFormStandardError) {
  // mu ± a alternating, 2n values (n even): sample variance a² 2n/(2n − 1), both windows' means
  // mu, so the change is the standard error of a window's mean over it: (a/mu) sqrt(2/(2n − 1)).
  const double mu = 3.0, a = 0.6;
  for (std::size_t n : {4, 16, 64}) {
    std::vector<double> x;
    for (std::size_t j = 0; j < 2 * n; ++j) x.push_back(j % 2 ? mu - a : mu + a);
    EXPECT_NEAR(MeanWindowChange(x, n, 0.05), a / mu * std::sqrt(2.0 / (2.0 * n - 1.0)), 1e-14) << n;
  }
  EXPECT_EQ(MeanWindowChange(std::vector<double>(32, 2.5), 16, 0.05), 0.0);  // constant: known exactly
  EXPECT_EQ(MeanWindowChange(std::vector<double>(32, 0.0), 16, 0.05), 0.0);  // nothing heats
}

TEST(PeriodicMean, ATrendBetweenTheWindowsIsNotSteady) {
  // The same scatter with the last window 10 % above the one before. The step adds its own
  // variance (0.05² about the mean 1.05): SE = sqrt(2 · 0.05² · 2n/(2n − 1) / n), and the change is
  // tol × 0.1 / (3 √2 SE), 2.7 × the tolerance, where without the step it passes.
  const std::size_t n = 64;
  std::vector<double> flat, stepped;
  for (std::size_t j = 0; j < 2 * n; ++j) {
    const double noise = j % 2 ? -0.05 : 0.05;
    flat.push_back(1.0 + noise);
    stepped.push_back((j < n ? 1.1 : 1.0) + noise);  // newest first: the last window higher
  }
  const double tol = 0.05;
  EXPECT_LT(MeanWindowChange(flat, n, tol), tol);
  const double se = std::sqrt(2.0 * 0.05 * 0.05 * (2.0 * n) / (2.0 * n - 1.0) / static_cast<double>(n));
  EXPECT_NEAR(MeanWindowChange(stepped, n, tol), tol * 0.1 / (3.0 * std::sqrt(2.0) * se), 1e-12);
  EXPECT_GT(MeanWindowChange(stepped, n, tol), 2.5 * tol);
}

/// The detector's use of the criterion on a stationary series of per-period heat: judged once two
/// windows exist, settled when it passes twice a window apart (detected, then recorded and
/// compared again). The period at which it settles, or -1 by `periods`.
long SettlingPeriod(const std::vector<double>& heat, long base, bool widen, double tol) {
  MeanWindow window(base);
  long recording_ends = -1;
  for (long k = 1; k < static_cast<long>(heat.size()); ++k) {
    const long n = window.window();
    const bool judged = k >= 2 * n;
    bool passed = false;
    if (judged) {
      std::vector<double> newest_first(heat.rend() - k - 1, heat.rend());
      newest_first.resize(2 * n);
      passed = MeanWindowChange(newest_first, n, tol) < tol;
    }
    if (recording_ends >= 0 && k >= recording_ends) {
      if (passed) return k;
      recording_ends = -1;
    } else if (recording_ends < 0 && passed) {
      recording_ends = k + n;
    }
    if (widen) window.After(judged, passed);
  }
  return -1;
}

TEST(PeriodicMean, IntermittentHeatSettlesOnceTheWindowWidens) {
  // Heat per period scattering by 30 % of its mean (an intermittently clapping crack): a window
  // of 16 periods knows its mean to ~7.5 %, above a 5 % tolerance, and needs that twice; widened
  // to 64 periods it knows it to ~3.8 %.
  std::mt19937 random(7);
  std::normal_distribution<double> scatter(1.0, 0.3);
  std::vector<double> heat(4000);
  for (double& h : heat) h = std::max(0.0, scatter(random));
  const long fixed = SettlingPeriod(heat, 16, false, 0.05), widened = SettlingPeriod(heat, 16, true, 0.05);
  std::printf("settled at period %ld with a fixed window of 16, %ld widening\n", fixed, widened);
  EXPECT_GT(widened, 0);
  EXPECT_LE(widened, 400);  // 32 + 32 failures at 16, 64 at 32, then two windows of 64 and one recorded
  EXPECT_TRUE(fixed < 0 || fixed > 2 * widened);
  MeanWindow window(16);
  for (int k = 0; k < 1000; ++k) window.After(true, false);
  EXPECT_EQ(window.window(), MeanWindow::kWidening * 16);  // never wider
  window.Reset();
  EXPECT_EQ(window.window(), 16);
  EXPECT_EQ(window.failures(), 0);
}

}  // namespace
}  // namespace vibrotherm::coupling

// Requirement (issue 43, item 4): the progress of a periodic scene tells how far it is from
// periodic and how long it will watch. The outlook fits the log of the change per period:
// an exponentially decaying transient is predicted to reach the tolerance where it does; a
// change that stays put (noise above the tolerance) or grows is never predicted to.
#include <gtest/gtest.h>

#include <cmath>

#include "vibrotherm/coupling/continuation/periodic_outlook.hpp"

namespace vibrotherm::coupling {
namespace {

TEST(PeriodicOutlook, AnExponentialTransientReachesTheToleranceWhereItDoes) {
  PeriodicOutlook outlook;
  const double tol = 3e-4, rate = 0.05;  // change = 0.1 exp(-0.05 k): below tol at k = ln(0.1/tol)/0.05 = 116.2
  outlook.Add(0.0, INFINITY);  // the detector cannot compare yet: no sample, but the stretch starts here
  for (int k = 1; k <= 20; ++k) outlook.Add(k, 0.1 * std::exp(-rate * k));
  EXPECT_NEAR(outlook.PeriodsToTolerance(tol), std::log(0.1 / tol) / rate - 20.0, 1e-9);
  EXPECT_NEAR(outlook.change(), 0.1 * std::exp(-rate * 20), 1e-15);
  EXPECT_EQ(outlook.watched(), 20.0);
  EXPECT_EQ(outlook.PeriodsToTolerance(1.0), 0.0);  // below already
}

TEST(PeriodicOutlook, NoPredictionWithoutATrendOrSamples) {
  PeriodicOutlook outlook;
  for (int k = 0; k < 3; ++k) outlook.Add(k, 0.1 * std::exp(-0.5 * k));
  EXPECT_TRUE(std::isinf(outlook.PeriodsToTolerance(1e-4)));  // three samples: too few
  outlook.Reset();
  for (int k = 0; k < 30; ++k) outlook.Add(k, 2e-3 * (1.0 + 0.2 * std::sin(1.7 * k)));  // noise, no trend
  EXPECT_TRUE(std::isinf(outlook.PeriodsToTolerance(3e-4)));
  outlook.Reset();
  for (int k = 0; k < 30; ++k) outlook.Add(k, 1e-3 * std::exp(0.01 * k));  // growing
  EXPECT_TRUE(std::isinf(outlook.PeriodsToTolerance(3e-4)));
  outlook.Reset();
  EXPECT_TRUE(std::isinf(outlook.change()));
  EXPECT_EQ(outlook.watched(), 0.0);
}

TEST(PeriodicOutlook, FitsTheLastSamplesOnly) {
  // A fast early decay, then a slow one: the prediction follows the recent, slow rate.
  PeriodicOutlook outlook;
  for (int k = 0; k < 10; ++k) outlook.Add(k, std::exp(-1.0 * k));
  const double at = std::exp(-9.0);
  for (int k = 10; k < 40; ++k) outlook.Add(k, at * std::exp(-0.02 * (k - 9)));
  const double now = at * std::exp(-0.02 * 30);
  EXPECT_NEAR(outlook.PeriodsToTolerance(now * std::exp(-0.02 * 50)), 50.0, 1e-6);
}

}  // namespace
}  // namespace vibrotherm::coupling

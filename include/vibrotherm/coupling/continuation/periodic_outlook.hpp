// How far a steady stretch of the source is from periodic, and how long until it is
// (issue 43): the detector's change per period (periodic_detector.hpp) at each period
// boundary, a straight line through the logarithm of the last samples' changes, and
// where that line crosses the tolerance. A transient decays roughly exponentially, so
// the line predicts the periods still to watch; a change that does not shrink by more
// than its scatter (contact noise above the tolerance, a drift, chaos) has no prediction.
// Plain C++ (unit-tested).
#pragma once

#include <cstddef>
#include <deque>
#include <utility>

namespace vibrotherm::coupling {

class PeriodicOutlook {
 public:
  /// A new steady stretch (or the waves jumped ahead): no samples.
  void Reset();
  /// The change at source period `period` (periods since the start, any origin); inf while
  /// the detector cannot compare yet (ignored).
  void Add(double period, double change);
  /// Periods after the last sample until the change falls below tol on the fitted line;
  /// +inf when it does not shrink or fewer than kMinSamples changes are known; 0 when below.
  double PeriodsToTolerance(double tol) const;
  /// Whether enough changes are known for a trend (kMinSamples).
  bool predictable() const { return samples_.size() >= kMinSamples; }
  /// The last finite change (inf when none).
  double change() const;
  /// Source periods from the first sample of the stretch to the last.
  double watched() const;

  static constexpr std::size_t kMinSamples = 4, kFitSamples = 12;

 private:
  std::deque<std::pair<double, double>> samples_;  ///< (period, log change), the last kFitSamples
  double first_ = -1.0, last_ = -1.0;              ///< the stretch's first and last sampled period
};

}  // namespace vibrotherm::coupling

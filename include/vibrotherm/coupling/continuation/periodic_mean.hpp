// -periodic_mode mean (a statistically steady state, periodic_detector.hpp): the criterion on
// per-period heat (friction or damping energy per source period) and the window it is judged
// over. The last window's mean must be known to the tolerance (its standard error over the
// mean) with no trend (the two last windows' means within 3 standard errors of their
// difference). A crack that claps intermittently scatters so much per period that a window of
// -periodic_window periods rarely knows its mean to the tolerance, and a continuation needs it
// twice, a window apart (detected, then recorded and compared once more): the window doubles
// after two windows' worth of failed samples at it (an odd pass among them does not reset the
// count), up to kWidening times -periodic_window. The standard error falls as 1/sqrt(window);
// the trend test only gets stricter.
// Plain C++ (unit-tested).
#pragma once

#include <cstddef>
#include <vector>

namespace vibrotherm::coupling {

/// The change of per-period values (newest first, at least 2n of them; the last 2n are judged):
/// max(standard error of the last n's mean / |that mean|, tol × trend), trend = |mean of the last
/// n − mean of the n before| / (3 √2 standard error). 0 when their mean is not positive (nothing
/// of this kind heats).
double MeanWindowChange(const std::vector<double>& newest_first, std::size_t n, double tol);

/// The window of the mean criterion and its widening.
class MeanWindow {
 public:
  static constexpr long kWidening = 4;  ///< the widest window, in -periodic_window's
  explicit MeanWindow(long base = 4) : base_(base), window_(base) {}
  /// A new steady stretch (or the waves jumped ahead): back to -periodic_window.
  void Reset() { window_ = base_, failures_ = 0; }
  /// After a sample: `judged` when the criterion could compare two windows, `passed` when it
  /// held. True when the window just doubled.
  bool After(bool judged, bool passed);
  long window() const { return window_; }
  long failures() const { return failures_; }
  /// A checkpoint's window and failures.
  void Restore(long window, long failures) { window_ = window, failures_ = failures; }

 private:
  long base_, window_;
  long failures_ = 0;  ///< judged samples at this window that did not pass
};

}  // namespace vibrotherm::coupling

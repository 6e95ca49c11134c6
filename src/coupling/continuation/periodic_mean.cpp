#include "vibrotherm/coupling/continuation/periodic_mean.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::coupling {

double MeanWindowChange(const std::vector<double>& newest_first, std::size_t n, double tol) {
  double sum[2] = {0.0, 0.0}, squares = 0.0;  // the older and the last window's values
  for (std::size_t j = 0; j < 2 * n; ++j) {
    const double x = newest_first[j];
    sum[j < n ? 1 : 0] += x;
    squares += x * x;
  }
  const double mean = (sum[0] + sum[1]) / (2.0 * n);
  if (mean <= 0.0) return 0.0;
  const double variance = std::max(0.0, squares / (2.0 * n) - mean * mean) * (2.0 * n) / (2.0 * n - 1.0);
  const double error = std::sqrt(variance / n);  // of one window's mean
  const double last = sum[1] / n, before = sum[0] / n;
  const double trend = error > 0.0 ? std::abs(last - before) / (3.0 * std::sqrt(2.0) * error) : 0.0;
  return std::max(error / std::abs(last), tol * trend);
}

bool MeanWindow::After(bool judged, bool passed) {
  if (judged && !passed) ++failures_;  // a pass now and then does not reset: a continuation needs two
  if (failures_ < 2 * window_ || window_ >= kWidening * base_) return false;
  failures_ = 0;
  window_ *= 2;
  return true;
}

}  // namespace vibrotherm::coupling

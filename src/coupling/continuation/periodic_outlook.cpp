#include "vibrotherm/coupling/continuation/periodic_outlook.hpp"

#include <cmath>
#include <limits>

namespace vibrotherm::coupling {

void PeriodicOutlook::Reset() {
  samples_.clear();
  first_ = last_ = -1.0;
}

void PeriodicOutlook::Add(double period, double change) {
  if (first_ < 0.0) first_ = period;
  last_ = period;
  if (!(change > 0.0) || !std::isfinite(change)) return;
  samples_.emplace_back(period, std::log(change));
  while (samples_.size() > kFitSamples) samples_.pop_front();
}

double PeriodicOutlook::PeriodsToTolerance(double tol) const {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  if (samples_.size() < kMinSamples) return kNever;
  if (samples_.back().second < std::log(tol)) return 0.0;
  // Least squares: log change = a + b (period − mean period).
  const double n = static_cast<double>(samples_.size());
  double px = 0.0, py = 0.0;
  for (const auto& [p, y] : samples_) px += p / n, py += y / n;
  double sxx = 0.0, sxy = 0.0;
  for (const auto& [p, y] : samples_) sxx += (p - px) * (p - px), sxy += (p - px) * (y - py);
  const double b = sxx > 0.0 ? sxy / sxx : 0.0;
  double residual = 0.0;
  for (const auto& [p, y] : samples_) residual += std::pow(y - py - b * (p - px), 2);
  const double error = sxx > 0.0 ? std::sqrt(residual / (n - 2.0) / sxx) : INFINITY;
  // A trend toward the tolerance: shrinking by 1 % a period or more, beyond twice the slope's
  // standard error (a contact's period-to-period noise is no trend).
  if (!(b + 2.0 * error < std::log(0.99))) return kNever;
  const double at_last = py + b * (samples_.back().first - px);
  return std::max(0.0, (std::log(tol) - at_last) / b);
}

double PeriodicOutlook::change() const {
  return samples_.empty() ? std::numeric_limits<double>::infinity() : std::exp(samples_.back().second);
}

double PeriodicOutlook::watched() const { return first_ < 0.0 ? 0.0 : last_ - first_; }

}  // namespace vibrotherm::coupling

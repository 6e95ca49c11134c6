#include "vibrotherm/coupling/exchange/periodic_replay.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::coupling {

void PeriodicReplay::Start(double t, const std::vector<double>& values) {
  start_ = t;
  recording_ = true;
  phases_ = {0.0};
  samples_ = {values};
}

void PeriodicReplay::Sample(double t, const std::vector<double>& values) {
  phases_.push_back(t - start_);
  samples_.push_back(values);
}

std::vector<double> PeriodicReplay::increase() const {
  std::vector<double> d(samples_.back());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] -= samples_.front()[i];
  return d;
}

std::vector<double> PeriodicReplay::At(double t, ReplayMode mode) const {
  const double P = span(), tau = t - end();
  // Whole spans, rounded so that a time on a period boundary lands on it (not one ulp short).
  double n = std::floor(tau / P + 1e-9);
  double phi = std::max(0.0, tau - n * P);
  const std::vector<double>& last = samples_.back();
  const std::vector<double> rise = increase();
  std::vector<double> values(last.size());
  if (mode == ReplayMode::Averaged) {
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = last[i] + (tau / P) * rise[i];
    return values;
  }
  // Phase-locked: the recorded samples bracketing φ.
  const std::size_t hi = std::min<std::size_t>(
      phases_.size() - 1, static_cast<std::size_t>(std::upper_bound(phases_.begin(), phases_.end(), phi * (1 + 1e-12)) -
                                                    phases_.begin()));
  const std::size_t lo = hi - 1;
  const double w = std::clamp((phi - phases_[lo]) / (phases_[hi] - phases_[lo]), 0.0, 1.0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double within = (1 - w) * samples_[lo][i] + w * samples_[hi][i] - samples_.front()[i];
    values[i] = last[i] + n * rise[i] + within;
  }
  return values;
}

std::vector<double> PeriodicReplay::item(std::size_t i) const {
  std::vector<double> values;
  for (const std::vector<double>& s : samples_) values.push_back(s[i]);
  return values;
}

void PeriodicReplay::Restore(double start, std::vector<double> phases, const std::vector<std::vector<double>>& items,
                             bool recording) {
  start_ = start;
  recording_ = recording;
  phases_ = std::move(phases);
  samples_.assign(phases_.size(), std::vector<double>(items.size()));
  for (std::size_t i = 0; i < items.size(); ++i)
    for (std::size_t k = 0; k < phases_.size(); ++k) samples_[k][i] = items[i][k];
}

}  // namespace vibrotherm::coupling

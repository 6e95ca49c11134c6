// A recorded period of a cumulative quantity per item (the friction energy W of
// each contact cell), replayed periodically after the recording (issue 24):
//   phase-locked  W(t) = W_end + n ΔW + (W_rec(φ) − W_start), W_rec linear between
//                 the recorded samples (exact at them: the heat steps of the period);
//   averaged      W(t) = W_end + (τ / span) ΔW (constant power),
// with τ = t − t_end = n·span + φ. Both equal W_end + n ΔW at whole periods, so
// a heat step spanning whole periods receives their energy exactly either way.
#pragma once

#include <cstddef>
#include <vector>

namespace vibrotherm::coupling {

enum class ReplayMode { Off, PhaseLocked, Averaged };

class PeriodicReplay {
 public:
  /// Starts a recording at t with the values then (phase 0).
  void Start(double t, const std::vector<double>& values);
  /// A sample while recording (t after the last one).
  void Sample(double t, const std::vector<double>& values);
  bool recording() const { return recording_; }
  /// The recording ends at its last sample: the recorded span.
  void Stop() { recording_ = false; }
  /// The values at t >= the recording's end, in `mode` (not Off).
  std::vector<double> At(double t, ReplayMode mode) const;
  /// The increase over one recorded span, per item.
  std::vector<double> increase() const;
  double span() const { return phases_.empty() ? 0.0 : phases_.back(); }
  double end() const { return start_ + span(); }
  bool empty() const { return phases_.size() < 2; }
  /// As numbers and back (checkpoints): the phases, and per item its samples.
  const std::vector<double>& phases() const { return phases_; }
  double start() const { return start_; }
  std::vector<double> item(std::size_t i) const;
  void Restore(double start, std::vector<double> phases, const std::vector<std::vector<double>>& items,
               bool recording);

 private:
  double start_ = 0.0;
  bool recording_ = false;
  std::vector<double> phases_;                ///< sample times − start
  std::vector<std::vector<double>> samples_;  ///< per sample, per item
};

}  // namespace vibrotherm::coupling

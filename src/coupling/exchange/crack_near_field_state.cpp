// The near field in checkpoints (taken after a heat step): the heat step ends
// of the window, its per-cell densities and wave-step energies (keyed by the
// contact cells' origin: any partition restores them), the last steps' terms of
// D (this rank's sums; another partition puts them on rank 0), and the step
// length of the equal-step responses, which a restart recomputes with the very same step.
#include "vibrotherm/coupling/exchange/crack_near_field.hpp"

namespace vibrotherm::coupling {

PetscErrorCode CrackNearField::Save(store::Checkpoint& checkpoint, const std::vector<long long>& keys) const {
  PetscFunctionBeginUser;
  if (!any()) PetscFunctionReturn(0);
  checkpoint.PutShared("near_field/ends", std::vector<double>(ends_.begin(), ends_.end()));
  checkpoint.PutShared("near_field/equal_step", {equal_step_});
  // The kept steps' term counts (the same on every rank), then the terms padded to K
  // (sums of the ranks' parts add up whatever the partition).
  std::vector<double> counts, terms;
  const std::size_t K = static_cast<std::size_t>(steps_);
  for (const Probe& probe : probes_)
    for (std::size_t j = 0; probe.active && j < 3; ++j) {
      const bool kept = j < probe.terms.size();
      counts.push_back(kept ? static_cast<double>(probe.terms[j].size()) : -1.0);
      for (std::size_t k = 0; k < K; ++k) terms.push_back(kept && k < probe.terms[j].size() ? probe.terms[j][k] : 0.0);
    }
  checkpoint.PutShared("near_field/term_counts", counts);
  checkpoint.PutPerRank("near_field/terms", terms);
  std::vector<double> times;
  for (const Sample& s : fine_) times.push_back(s.t);
  checkpoint.PutShared("near_field/times", times);
  const std::size_t cells = keys.size(), n = fine_.size(), m = density_.size();
  std::vector<double> energy(cells * n), density(cells * m);  // cell-major: a cell's history is one item
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t k = 0; k < n; ++k) energy[c * n + k] = fine_[k].W[c];
    for (std::size_t k = 0; k < m; ++k) density[c * m + k] = density_[k][c];
  }
  checkpoint.PutKeyed("near_field/energy", keys, static_cast<int>(n), energy);
  checkpoint.PutKeyed("near_field/density", keys, static_cast<int>(m), density);
  PetscFunctionReturn(0);
}

PetscErrorCode CrackNearField::Restore(const store::Checkpoint& checkpoint, const std::vector<long long>& keys) {
  PetscFunctionBeginUser;
  if (!any()) PetscFunctionReturn(0);
  std::vector<double> ends, step, times, energy, density;
  PetscCall(checkpoint.GetShared("near_field/ends", &ends));
  PetscCall(checkpoint.GetShared("near_field/equal_step", &step, 1));
  PetscCall(checkpoint.GetShared("near_field/times", &times));
  const std::size_t cells = keys.size(), n = times.size(), m = ends.size() - 1;  // a density per step of the window
  PetscCall(checkpoint.GetKeyed("near_field/energy", keys, static_cast<int>(n), &energy));
  PetscCall(checkpoint.GetKeyed("near_field/density", keys, static_cast<int>(m), &density));
  ends_.assign(ends.begin(), ends.end());
  fine_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    fine_.push_back({times[k], std::vector<double>(cells)});
    for (std::size_t c = 0; c < cells; ++c) fine_.back().W[c] = energy[c * n + k];
  }
  density_.clear();
  for (std::size_t k = 0; k < m; ++k) {
    density_.push_back(std::vector<double>(cells));
    for (std::size_t c = 0; c < cells; ++c) density_.back()[c] = density[c * m + k];
  }
  if (step[0] > 0.0) PetscCall(EqualStepResponses(step[0]));
  std::vector<double> counts, terms;
  PetscCall(checkpoint.GetShared("near_field/term_counts", &counts));
  PetscCall(checkpoint.GetPerRank("near_field/terms", &terms));
  const std::size_t K = static_cast<std::size_t>(steps_);
  std::size_t slot = 0;
  for (Probe& probe : probes_) {
    probe.terms.clear();
    for (std::size_t j = 0; probe.active && j < 3; ++j, ++slot) {
      if (counts.at(slot) < 0) continue;
      const auto from = terms.begin() + static_cast<long>(slot * K);
      probe.terms.emplace_back(from, from + static_cast<long>(counts[slot]));
    }
  }
  Jumps();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

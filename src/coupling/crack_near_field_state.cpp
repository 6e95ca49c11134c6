// The near field in checkpoints (taken after a heat step): the heat step ends
// of the window, its per-cell densities and wave-step energies (keyed by the
// contact cells' origin: any partition restores them), and the step length of
// the discrete responses, which a restart recomputes with the very same step.
#include "vibrotherm/coupling/crack_near_field.hpp"

namespace vibrotherm::coupling {

PetscErrorCode CrackNearField::Save(io::Checkpoint& checkpoint, const std::vector<long long>& keys) const {
  PetscFunctionBeginUser;
  if (!any()) PetscFunctionReturn(0);
  checkpoint.PutShared("near_field/ends", std::vector<double>(ends_.begin(), ends_.end()));
  checkpoint.PutShared("near_field/response_step", {response_step_});
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

PetscErrorCode CrackNearField::Restore(const io::Checkpoint& checkpoint, const std::vector<long long>& keys) {
  PetscFunctionBeginUser;
  if (!any()) PetscFunctionReturn(0);
  std::vector<double> ends, step, times, energy, density;
  PetscCall(checkpoint.GetShared("near_field/ends", &ends));
  PetscCall(checkpoint.GetShared("near_field/response_step", &step, 1));
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
  if (step[0] > 0.0) PetscCall(UpdateResponses(step[0]));
  Jumps();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

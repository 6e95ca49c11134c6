// A heat source's periodic replay (periodic_replay.hpp) in a checkpoint: the mode it
// plays in, whether it is recording, its start and phases (shared), and each item's
// samples keyed by the item's checkpoint key (a contact cell, a heat dof), so a
// restart on another partition finds them.
#pragma once

#include <string>
#include <vector>

#include "vibrotherm/coupling/exchange/periodic_replay.hpp"
#include "vibrotherm/store/checkpoint.hpp"

namespace vibrotherm::coupling {

/// Under name/replay and name/replay_samples.
void PutReplay(store::Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys,
               const PeriodicReplay& replay, ReplayMode mode);
PetscErrorCode GetReplay(const store::Checkpoint& checkpoint, const std::string& name,
                         const std::vector<long long>& keys, PeriodicReplay* replay, ReplayMode* mode);

}  // namespace vibrotherm::coupling

#include "vibrotherm/coupling/exchange/replay_checkpoint.hpp"

namespace vibrotherm::coupling {

void PutReplay(store::Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys,
               const PeriodicReplay& replay, ReplayMode mode) {
  std::vector<double> samples;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::vector<double> item = replay.item(i);
    samples.insert(samples.end(), item.begin(), item.end());
  }
  std::vector<double> phases = replay.phases();
  phases.insert(phases.begin(), {static_cast<double>(mode), replay.recording() ? 1.0 : 0.0, replay.start()});
  checkpoint.PutShared(name + "/replay", phases);
  checkpoint.PutKeyed(name + "/replay_samples", keys, static_cast<int>(replay.phases().size()), samples);
}

PetscErrorCode GetReplay(const store::Checkpoint& checkpoint, const std::string& name,
                         const std::vector<long long>& keys, PeriodicReplay* replay, ReplayMode* mode) {
  PetscFunctionBeginUser;
  std::vector<double> header, samples;
  PetscCall(checkpoint.GetShared(name + "/replay", &header));
  const std::size_t phases = header.size() - 3;
  PetscCall(checkpoint.GetKeyed(name + "/replay_samples", keys, static_cast<int>(phases), &samples));
  std::vector<std::vector<double>> items(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    items[i].assign(samples.begin() + static_cast<std::ptrdiff_t>(i * phases),
                    samples.begin() + static_cast<std::ptrdiff_t>((i + 1) * phases));
  replay->Restore(header[2], std::vector<double>(header.begin() + 3, header.end()), items, header[1] != 0.0);
  *mode = static_cast<ReplayMode>(static_cast<int>(header[0]));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

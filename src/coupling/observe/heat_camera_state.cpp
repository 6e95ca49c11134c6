// The IR camera in checkpoints: where it is in its frames, the open window's
// running integral and the last sample (per pixel, keyed by the pixel index),
// the noise generator and the peaks so far (rank 0), and camera.h5 reopened
// where the checkpoint left it; the defect's share of the open window and the
// frames' verdicts (camera_verdict.hpp) too.
#include <sstream>

#include "vibrotherm/coupling/observe/heat_camera.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::coupling {
namespace {

std::vector<long long> OwnedPixels(Vec v) {
  PetscInt start = 0, end = 0;
  VecGetOwnershipRange(v, &start, &end);
  std::vector<long long> keys;
  for (PetscInt i = start; i < end; ++i) keys.push_back(i);
  return keys;
}

}  // namespace

PetscErrorCode HeatCamera::Save(store::Checkpoint& checkpoint) const {
  PetscFunctionBeginUser;
  checkpoint.PutShared("camera/clock", {static_cast<double>(frame_), t_prev_});
  const std::vector<long long> keys = OwnedPixels(previous_);
  PetscCall(store::PutOwnedValues(checkpoint, "camera/previous", keys, previous_));
  PetscCall(store::PutOwnedValues(checkpoint, "camera/integral", keys, integral_));
  if (share_ == DefectShare::Partial) {
    PetscCall(store::PutOwnedValues(checkpoint, "camera/defect_previous", keys, defect_previous_));
    PetscCall(store::PutOwnedValues(checkpoint, "camera/defect_integral", keys, defect_integral_));
  }
  std::vector<double> verdicts;
  for (const FrameVerdict& f : verdicts_)
    verdicts.insert(verdicts.end(), {f.t_end, f.total_peak, f.total_pixel, f.defect_peak, f.defect_pixel,
                                     f.background_peak, f.defect_at_total_peak});
  checkpoint.PutShared("camera/verdicts", verdicts);
  // Rank 0 holds these: the checkpoint keeps rank 0's copy of shared items.
  std::ostringstream noise;
  noise << random_;
  checkpoint.PutText("camera/noise", noise.str());
  checkpoint.PutShared("camera/peak_clean", peak_clean_);
  checkpoint.PutShared("camera/peak_noisy", peak_noisy_);
  checkpoint.PutShared("camera/times", file_.times());
  PetscFunctionReturn(0);
}

PetscErrorCode HeatCamera::Restore(const store::Checkpoint& checkpoint, const std::string& dir) {
  PetscFunctionBeginUser;
  std::vector<double> clock, times;
  PetscCall(checkpoint.GetShared("camera/clock", &clock, 2));
  frame_ = static_cast<PetscInt>(clock[0]);
  t_prev_ = clock[1];
  const std::vector<long long> keys = OwnedPixels(previous_);
  PetscCall(store::GetOwnedValues(checkpoint, "camera/previous", keys, previous_));
  PetscCall(store::GetOwnedValues(checkpoint, "camera/integral", keys, integral_));
  if (share_ == DefectShare::Partial && checkpoint.Has("camera/defect_integral")) {
    PetscCall(store::GetOwnedValues(checkpoint, "camera/defect_previous", keys, defect_previous_));
    PetscCall(store::GetOwnedValues(checkpoint, "camera/defect_integral", keys, defect_integral_));
  }
  std::vector<double> v;
  verdicts_.clear();
  if (checkpoint.Has("camera/verdicts")) {
    PetscCall(checkpoint.GetShared("camera/verdicts", &v));
    for (std::size_t i = 0; i + FrameVerdict::kValues <= v.size(); i += FrameVerdict::kValues)
      verdicts_.push_back({v[i], v[i + 1], v[i + 2], v[i + 3], v[i + 4], v[i + 5], v[i + 6]});
  }
  std::string noise;
  PetscCall(checkpoint.GetText("camera/noise", &noise));
  std::istringstream(noise) >> random_;
  PetscCall(checkpoint.GetShared("camera/peak_clean", &peak_clean_));
  PetscCall(checkpoint.GetShared("camera/peak_noisy", &peak_noisy_));
  PetscCall(checkpoint.GetShared("camera/times", &times));
  if (frames_ > 0)
    PetscCall(RunOnRoot(comm_, [&] { file_.Reopen(dir + "/camera.h5", grid_, static_cast<int>(frame_), times); }));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

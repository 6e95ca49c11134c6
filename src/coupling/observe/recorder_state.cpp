// The recorder in checkpoints: how long each output file was, what the summary
// has gathered so far (probe peaks, rises at output times, the field peak),
// the probes' last temperatures and the field outputs written.
#include "vibrotherm/coupling/observe/recorder.hpp"

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {
namespace {

/// A map int → double as [key, value, ...].
std::vector<double> Flatten(const std::map<int, double>& map) {
  std::vector<double> flat;
  for (const auto& [key, value] : map) flat.insert(flat.end(), {static_cast<double>(key), value});
  return flat;
}

std::map<int, double> Unflatten(const double* flat, std::size_t n) {
  std::map<int, double> map;
  for (std::size_t i = 0; i + 1 < n; i += 2) map[static_cast<int>(flat[i])] = flat[i + 1];
  return map;
}

}  // namespace

PetscErrorCode Recorder::Save(store::Checkpoint& checkpoint) const {
  PetscFunctionBeginUser;
  long long probes = 0, energy = 0, crack = -1;
  VibrothermCallIo(PETSC_COMM_SELF, probes = probes_.bytes(); energy = energy_.bytes(); crack = crack_state_.bytes());
  checkpoint.PutShared("recorder/bytes", {static_cast<double>(probes), static_cast<double>(energy),
                                          static_cast<double>(crack), static_cast<double>(outputs_written_)});
  checkpoint.PutShared("recorder/energy_maxima", energy_.maxima());
  checkpoint.PutShared("recorder/last_temperatures", last_T_);
  checkpoint.PutShared("recorder/written_times", written_times_);
  checkpoint.PutShared("recorder/next_output", {static_cast<double>(next_output_)});
  checkpoint.PutShared("recorder/probe_peaks", Flatten(summary_->probe_max_temperature_rise));
  std::vector<double> rises;  // per output: t, n, then n (probe, rise) pairs
  for (const auto& [t, by_probe] : summary_->output_temperature_rise) {
    const std::vector<double> flat = Flatten(by_probe);
    rises.insert(rises.end(), {t, static_cast<double>(flat.size())});
    rises.insert(rises.end(), flat.begin(), flat.end());
  }
  checkpoint.PutShared("recorder/output_rises", rises);
  const io::FieldPeakSummary& p = field_peak_.peak();
  checkpoint.PutShared("recorder/field_peak", {p.known ? 1.0 : 0.0, p.rise, p.t, p.x, p.y, p.z});
  if (camera_) PetscCall(camera_->Save(checkpoint));
  PetscCall(source_power_.Save(checkpoint));
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::Restore(const store::Checkpoint& checkpoint, const wave::WaveSolver* waves,
                                 const heat::HeatSolver* heat) {
  PetscFunctionBeginUser;
  std::vector<double> v;
  PetscCall(checkpoint.GetShared("recorder/energy_maxima", &v, 2));
  energy_.set_maxima(v);
  PetscCall(checkpoint.GetShared("recorder/last_temperatures", &last_T_));
  PetscCall(checkpoint.GetShared("recorder/probe_peaks", &v));
  summary_->probe_max_temperature_rise = Unflatten(v.data(), v.size());
  PetscCall(checkpoint.GetShared("recorder/output_rises", &v));
  summary_->output_temperature_rise.clear();
  for (std::size_t i = 0; i + 1 < v.size(); i += 2 + static_cast<std::size_t>(v[i + 1]))
    summary_->output_temperature_rise.push_back({v[i], Unflatten(&v[i + 2], static_cast<std::size_t>(v[i + 1]))});
  PetscCall(checkpoint.GetShared("recorder/field_peak", &v, 6));
  field_peak_.set_peak({v[0] != 0.0, v[1], v[2], v[3], v[4], v[5]});
  if (camera_) PetscCall(camera_->Restore(checkpoint, dir_));
  PetscCall(checkpoint.GetShared("recorder/written_times", &written_times_));
  if (fields_.open() && checkpoint.same_ranks()) {  // index what the .partial holds already
    replaying_ = true;
    fields_.set_index_only(true);
    for (double t : written_times_) PetscCall(WriteFields(t, waves, heat));
    fields_.set_index_only(false);
    replaying_ = false;
  }
  outputs_written_ = static_cast<int>(written_times_.size());
  PetscCall(checkpoint.GetShared("recorder/next_output", &v, 1));
  next_output_ = static_cast<std::size_t>(v[0]);
  PetscFunctionReturn(0);
}

void Recorder::Keep() {
  probes_.Keep();
  energy_.Keep();
  crack_state_.Keep();
  source_power_.Keep();
}

}  // namespace vibrotherm::coupling

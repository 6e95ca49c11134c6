// The periodic continuation in checkpoints: the detector's samples (a restart
// finds periodicity where the uninterrupted run does), a recording under way
// (the sources keep theirs), and a continuation's ladder (the waves' kept state
// is the wave component's own state, suspended; the heat holds θ − D).
#include "vibrotherm/coupling/continuation/periodic_continuation.hpp"

#include <cmath>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {
namespace {

constexpr std::size_t kRowValues = 16;

std::vector<double> Flatten(const io::EnergyRow& r) {
  return {r.t,          r.work_source,  r.kinetic,      r.strain,         r.radiated,
          r.interface_stored, r.dissipated, r.heat_deposited, r.heat_content, r.heat_boundary_loss,
          r.integrator_correction, r.heat_friction, r.heat_thermoelastic, r.work_thermal, r.damped,
          r.heat_damping};
}

io::EnergyRow Unflatten(const double* v) {
  io::EnergyRow r;
  r.t = v[0], r.work_source = v[1], r.kinetic = v[2], r.strain = v[3], r.radiated = v[4];
  r.interface_stored = v[5], r.dissipated = v[6], r.heat_deposited = v[7], r.heat_content = v[8];
  r.heat_boundary_loss = v[9], r.integrator_correction = v[10], r.heat_friction = v[11];
  r.heat_thermoelastic = v[12], r.work_thermal = v[13], r.damped = v[14], r.heat_damping = v[15];
  return r;
}

std::vector<long long> CellKeys(const ContinuedWaves& waves, const mesh::PointOrigin& origin) {
  std::vector<long long> keys;
  if (const interface::CrackInterface* crack = waves.crack())
    for (const interface::ContactCell& c : crack->cells()) keys.push_back(origin[c.plus]);
  return keys;
}

/// The waves' growing accounts (WaveComponent::Accumulated): the clock shared, the solver's other
/// accounts and the crack's dissipated energy per rank, every cell's W keyed by the cell.
void PutAccumulated(store::Checkpoint& checkpoint, const std::string& name, const std::vector<double>& values,
                    const std::vector<long long>& cells) {
  const std::size_t solver = values.size() - (cells.empty() ? 0 : cells.size() + 1);
  checkpoint.PutShared(name + "_clock", {values[0]});
  std::vector<double> ranks(values.begin() + 1, values.begin() + static_cast<std::ptrdiff_t>(solver));
  if (!cells.empty()) ranks.push_back(values.back());
  checkpoint.PutPerRank(name + "_ranks", ranks);
  checkpoint.PutKeyed(name + "_cells", cells, 1,
                      std::vector<double>(values.begin() + static_cast<std::ptrdiff_t>(solver),
                                          values.begin() + static_cast<std::ptrdiff_t>(solver + cells.size())));
}

PetscErrorCode GetAccumulated(const store::Checkpoint& checkpoint, const std::string& name,
                              const std::vector<long long>& cells, std::vector<double>* values) {
  PetscFunctionBeginUser;
  std::vector<double> clock, ranks, per_cell;
  PetscCall(checkpoint.GetShared(name + "_clock", &clock, 1));
  PetscCall(checkpoint.GetPerRank(name + "_ranks", &ranks));
  PetscCall(checkpoint.GetKeyed(name + "_cells", cells, 1, &per_cell));
  *values = clock;
  const std::size_t solver_ranks = cells.empty() ? ranks.size() : ranks.size() - 1;
  values->insert(values->end(), ranks.begin(), ranks.begin() + static_cast<std::ptrdiff_t>(solver_ranks));
  values->insert(values->end(), per_cell.begin(), per_cell.end());
  if (!cells.empty()) values->push_back(ranks.back());
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode PeriodicContinuation::Save(store::Checkpoint& checkpoint) const {
  PetscFunctionBeginUser;
  if (!on_) PetscFunctionReturn(0);
  const std::vector<long long> cells = CellKeys(*waves_, specimen_->wave_origin);
  std::vector<long long> dofs;
  PetscCall(mesh::OwnedDofKeys(specimen_->wave, specimen_->wave_origin, &dofs));
  long long bytes = 0;
  VibrothermCallIo(PETSC_COMM_SELF, bytes = detector_.bytes());
  checkpoint.PutShared("periodic/csv_bytes", {static_cast<double>(bytes)});
  checkpoint.PutShared("periodic/state", {static_cast<double>(phase_), static_cast<double>(multiple_), record_start_,
                                          record_end_, skip_stretch_, ladder_.t, ladder_.end, ladder_.rung,
                                          static_cast<double>(ladder_.count)});
  std::vector<double> rows = Flatten(row_start_), end = Flatten(row_end_), segments;
  rows.insert(rows.end(), end.begin(), end.end());
  checkpoint.PutShared("periodic/rows", rows);
  for (const Segment& s : segments_)
    segments.insert(segments.end(), {s.detected, s.suspended, s.resumed, static_cast<double>(s.multiple),
                                     static_cast<double>(s.periods), s.change, s.drift, s.projected, s.drift_error});
  checkpoint.PutShared("periodic/segments", segments);
  if (phase_ != Phase::kWatch) PutAccumulated(checkpoint, "periodic/start", accumulated_start_, cells);
  if (phase_ == Phase::kLadder) {
    PutAccumulated(checkpoint, "periodic/increments", increments_, cells);
    std::vector<long long> heat_dofs;
    PetscCall(mesh::OwnedDofKeys(heat_->solver().space().dm(), specimen_->heat_origin, &heat_dofs));
    checkpoint.PutShared("periodic/near_field", {static_cast<double>(near_field_.size())});
    for (std::size_t k = 0; k < near_field_.size(); ++k)
      PetscCall(store::PutOwnedValues(checkpoint, "periodic/near_field_" + std::to_string(k), heat_dofs, near_field_[k]));
  }
  PetscCall(detector_.Save(checkpoint, "periodic/detector", dofs, cells));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::Restore(const store::Checkpoint& checkpoint) {
  PetscFunctionBeginUser;
  if (!on_ || !checkpoint.Has("periodic/state")) PetscFunctionReturn(0);
  const std::vector<long long> cells = CellKeys(*waves_, specimen_->wave_origin);
  std::vector<long long> dofs;
  PetscCall(mesh::OwnedDofKeys(specimen_->wave, specimen_->wave_origin, &dofs));
  std::vector<double> state, rows, segments;
  PetscCall(checkpoint.GetShared("periodic/state", &state, 9));
  phase_ = static_cast<Phase>(static_cast<int>(state[0]));
  multiple_ = static_cast<PetscInt>(state[1]);
  record_start_ = state[2], record_end_ = state[3], skip_stretch_ = state[4];
  ladder_ = {state[5], state[6], state[7], static_cast<PetscInt>(state[8])};
  PetscCall(checkpoint.GetShared("periodic/rows", &rows, 2 * kRowValues));
  row_start_ = Unflatten(rows.data());
  row_end_ = Unflatten(rows.data() + kRowValues);
  PetscCall(checkpoint.GetShared("periodic/segments", &segments));
  segments_.clear();
  constexpr std::size_t kSegmentValues = 9;
  PetscCheck(segments.size() % kSegmentValues == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "-restart: the checkpoint's continuation segments have %zu values, not a multiple of %zu: written by "
             "another version of vibrotherm", segments.size(), kSegmentValues);
  for (std::size_t i = 0; i + kSegmentValues <= segments.size(); i += kSegmentValues)
    segments_.push_back({segments[i], segments[i + 1], segments[i + 2], static_cast<PetscInt>(segments[i + 3]),
                         static_cast<PetscInt>(segments[i + 4]), segments[i + 5], segments[i + 6], segments[i + 7],
                         segments[i + 8]});
  if (phase_ != Phase::kWatch) PetscCall(GetAccumulated(checkpoint, "periodic/start", cells, &accumulated_start_));
  if (phase_ == Phase::kLadder) {
    PetscCall(GetAccumulated(checkpoint, "periodic/increments", cells, &increments_));
    std::vector<long long> heat_dofs;
    PetscCall(mesh::OwnedDofKeys(heat_->solver().space().dm(), specimen_->heat_origin, &heat_dofs));
    const std::size_t count = static_cast<std::size_t>(checkpoint.Scalar("periodic/near_field"));
    for (Vec& d : near_field_) PetscCall(VecDestroy(&d));
    near_field_.assign(count, nullptr);
    for (std::size_t k = 0; k < count; ++k) {
      PetscCall(VecDuplicate(heat_->solver().rise(), &near_field_[k]));
      PetscCall(store::GetOwnedValues(checkpoint, "periodic/near_field_" + std::to_string(k), heat_dofs, near_field_[k]));
    }
    // The suspended waves are the kept state itself.
    kept_ = std::make_unique<store::Checkpoint>(PetscObjectComm((PetscObject)specimen_->wave));
    PetscCall(waves_->Snapshot(*specimen_, kept_.get()));
  }
  PetscCall(detector_.Restore(checkpoint, "periodic/detector", dofs, cells));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicDetector::Save(store::Checkpoint& checkpoint, const std::string& name,
                                      const std::vector<long long>& dofs, const std::vector<long long>& cells) const {
  PetscFunctionBeginUser;
  std::vector<double> times;
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const Snapshot& s = samples_[k];
    const std::string item = name + "_" + std::to_string(k);
    std::vector<double> row = Flatten(s.energy);
    row.push_back(s.t);
    times.insert(times.end(), row.begin(), row.end());
    PetscCall(store::PutOwnedValues(checkpoint, item + "_u", dofs, s.u));
    PetscCall(store::PutOwnedValues(checkpoint, item + "_v", dofs, s.v));
    std::vector<double> per_cell;
    for (std::size_t i = 0; i < cells.size(); ++i) per_cell.insert(per_cell.end(), {s.W[i], s.T[i], s.b0[i], s.b[i]});
    checkpoint.PutKeyed(item + "_cells", cells, 4, per_cell);
  }
  checkpoint.PutShared(name, times);
  checkpoint.PutShared(name + "_last_change", {last_change_});
  checkpoint.PutShared(name + "_window", {static_cast<double>(mean_window_.window()),
                                          static_cast<double>(mean_window_.failures())});
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicDetector::Restore(const store::Checkpoint& checkpoint, const std::string& name,
                                         const std::vector<long long>& dofs, const std::vector<long long>& cells) {
  PetscFunctionBeginUser;
  Reset();
  std::vector<double> times;
  PetscCall(checkpoint.GetShared(name, &times));
  PetscCheck(mass_ != nullptr || times.empty(), comm_, PETSC_ERR_ORDER, "periodic detector: restore after setup");
  std::vector<double> last;
  PetscCall(checkpoint.GetShared(name + "_last_change", &last, 1));
  last_change_ = last[0];
  std::vector<double> window;
  PetscCall(checkpoint.GetShared(name + "_window", &window, 2));
  mean_window_.Restore(static_cast<long>(window[0]), static_cast<long>(window[1]));
  for (std::size_t k = 0; (k + 1) * (kRowValues + 1) <= times.size(); ++k) {
    const std::string item = name + "_" + std::to_string(k);
    Snapshot s;
    s.energy = Unflatten(&times[k * (kRowValues + 1)]);
    s.t = times[k * (kRowValues + 1) + kRowValues];
    PetscCall(VecDuplicate(mass_, &s.u));
    PetscCall(VecDuplicate(mass_, &s.v));
    PetscCall(store::GetOwnedValues(checkpoint, item + "_u", dofs, s.u));
    PetscCall(store::GetOwnedValues(checkpoint, item + "_v", dofs, s.v));
    std::vector<double> per_cell;
    PetscCall(checkpoint.GetKeyed(item + "_cells", cells, 4, &per_cell));
    for (std::size_t i = 0; i < cells.size(); ++i) {
      s.W.push_back(per_cell[4 * i]);
      s.T.push_back(per_cell[4 * i + 1]);
      s.b0.push_back(per_cell[4 * i + 2]);
      s.b.push_back(per_cell[4 * i + 3]);
    }
    samples_.push_back(std::move(s));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

#include "vibrotherm/coupling/observe/source_power.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {

PetscErrorCode SourcePowerMeter::Open(MPI_Comm comm, const wave::SourceTimeFunction& signal, PetscInt window,
                                      const std::string& path, const store::Checkpoint* resume) {
  PetscFunctionBeginUser;
  comm_ = comm;
  signal_ = &signal;
  window_ = static_cast<double>(std::max<PetscInt>(1, window));
  const double bytes = resume ? resume->Scalar("source_power/csv_bytes") : -1.0;
  PetscCall(log_.Open(comm, path, std::isnan(bytes) ? -1 : static_cast<long long>(bytes)));
  if (resume && !std::isnan(bytes)) PetscCall(Restore(*resume));
  PetscFunctionReturn(0);
}

SourcePowerMeter::Accounts SourcePowerMeter::Interpolate(const Accounts& a, const Accounts& b, double t) {
  if (b.t <= a.t || t >= b.t) return b;
  if (t <= a.t) return a;
  const double w = (t - a.t) / (b.t - a.t);
  const auto mix = [w](double x, double y) { return x + w * (y - x); };
  return {t, mix(a.work, b.work), mix(a.friction, b.friction), mix(a.damping, b.damping), mix(a.radiated, b.radiated)};
}

io::SourcePowerRow SourcePowerMeter::Between(const Accounts& from, const Accounts& to, double periods) const {
  io::SourcePowerRow r;
  const double dt = to.t - from.t;
  r.t_start = from.t, r.t_end = to.t, r.periods = periods;
  if (dt <= 0.0) return r;
  r.frequency = periods / dt;
  r.amplitude = signal_->envelope(0.5 * (from.t + to.t));
  r.input = (to.work - from.work) / dt;
  r.friction = (to.friction - from.friction) / dt;
  r.damping = (to.damping - from.damping) / dt;
  r.radiated = (to.radiated - from.radiated) / dt;
  return r;
}

void SourcePowerMeter::OnEnergyRow(const io::EnergyRow& row) {
  if (stopped_ || !signal_) return;
  const Accounts now = From(row);
  if (!started_) {  // the first row (t = 0): the first boundary
    started_ = true;
    previous_ = boundary_ = now;
    boundary_cycle_ = std::floor(signal_->cycles(now.t) + 1e-9);
    return;
  }
  if (now.t <= previous_.t) return;
  const double last = std::floor(signal_->cycles(now.t) + 1e-9);
  if (last > boundary_cycle_) {
    // A continuation's rows span many periods at once, growing linearly: one row for all of them.
    const bool many = signal_->cycles(now.t) - signal_->cycles(previous_.t) > 2.0;
    const double step = many ? last - boundary_cycle_ : 1.0;
    for (double k = boundary_cycle_ + step; k <= last + 0.5; k += step) {
      const Accounts at = Interpolate(previous_, now, signal_->time_of_cycle(k));
      if (boundary_.t < at.t) Close(Between(boundary_, at, k - boundary_cycle_));
      boundary_ = at;
      boundary_cycle_ = k;
    }
  }
  previous_ = now;
}

void SourcePowerMeter::Close(const io::SourcePowerRow& row) {
  log_.Record(row);
  recent_.push_back(row);
  Trim(&recent_);
  double start, end;
  const double tol = 1e-9 * std::max(1.0, row.t_end);
  const bool steady = signal_->steady_stretch(0.5 * (row.t_start + row.t_end), &start, &end) &&
                      row.t_start >= start - tol && row.t_end <= end + tol;
  if (!steady) return;
  if (end != stretch_end_) {  // a new stretch: the last one's periods are final
    if (!stretch_.empty()) stretches_.push_back(LastPeriods(stretch_));
    stretch_.clear();
    stretch_end_ = end;
  }
  stretch_.push_back(row);
  Trim(&stretch_);
}

void SourcePowerMeter::Trim(std::vector<io::SourcePowerRow>* rows) const {
  double periods = 0.0;
  for (const io::SourcePowerRow& r : *rows) periods += r.periods;
  while (rows->size() > 1 && periods - rows->front().periods >= window_ - 1e-9) {
    periods -= rows->front().periods;
    rows->erase(rows->begin());
  }
}

io::SourcePowerRow SourcePowerMeter::LastPeriods(const std::vector<io::SourcePowerRow>& rows) const {
  Accounts from{rows.front().t_start}, to{rows.back().t_end};
  double periods = 0.0;
  for (const io::SourcePowerRow& r : rows) {  // powers × durations: the accounts' increases
    const double dt = r.t_end - r.t_start;
    to.work += r.input * dt, to.friction += r.friction * dt, to.damping += r.damping * dt, to.radiated += r.radiated * dt;
    periods += r.periods;
  }
  return Between(from, to, periods);
}

PetscErrorCode SourcePowerMeter::Finish(io::RunSummary* summary) {
  PetscFunctionBeginUser;
  if (!open()) PetscFunctionReturn(0);
  PetscCall(log_.Finish());
  std::vector<io::SourcePowerRow> stretches = stretches_;
  if (!stretch_.empty()) stretches.push_back(LastPeriods(stretch_));
  const bool steady = !stretches.empty();
  if (!steady && !recent_.empty()) stretches.push_back(LastPeriods(recent_));
  summary->source_power.clear();
  for (const io::SourcePowerRow& r : stretches) summary->source_power.push_back({r, steady});
  if (stretches.empty()) PetscFunctionReturn(0);
  const io::SourcePowerRow& r = stretches.back();
  const char* unit = summary->mesh.dimension == 3 ? "W" : "W/m";
  PetscCall(PetscPrintf(comm_,
                        "Source power over %.4g periods to t = %.6g s (%s): input %.4g %s, crack friction %.4g %s "
                        "(thermosonic efficiency %.3g %%), material damping %.4g %s, radiated %.4g %s\n",
                        r.periods, r.t_end, steady ? "the source steady" : "no steady source", r.input, unit,
                        r.friction, unit, 100.0 * r.efficiency(), r.damping, unit, r.radiated, unit));
  PetscFunctionReturn(0);
}

namespace {

std::vector<double> Flatten(const std::vector<io::SourcePowerRow>& rows) {
  std::vector<double> flat;
  for (const io::SourcePowerRow& r : rows)
    flat.insert(flat.end(), {r.t_start, r.t_end, r.periods, r.frequency, r.amplitude, r.input, r.friction, r.damping,
                             r.radiated});
  return flat;
}

std::vector<io::SourcePowerRow> Unflatten(const std::vector<double>& flat) {
  std::vector<io::SourcePowerRow> rows;
  for (std::size_t i = 0; i + 9 <= flat.size(); i += 9)
    rows.push_back({flat[i], flat[i + 1], flat[i + 2], flat[i + 3], flat[i + 4], flat[i + 5], flat[i + 6], flat[i + 7],
                    flat[i + 8]});
  return rows;
}

}  // namespace

PetscErrorCode SourcePowerMeter::Save(store::Checkpoint& checkpoint) const {
  PetscFunctionBeginUser;
  if (!open()) PetscFunctionReturn(0);
  long long bytes = 0;
  VibrothermCallIo(PETSC_COMM_SELF, bytes = log_.bytes());
  checkpoint.PutShared("source_power/csv_bytes", {static_cast<double>(bytes)});
  checkpoint.PutShared("source_power/state", {started_ ? 1.0 : 0.0, stopped_ ? 1.0 : 0.0, boundary_cycle_, stretch_end_});
  checkpoint.PutShared("source_power/accounts",
                       {previous_.t, previous_.work, previous_.friction, previous_.damping, previous_.radiated,
                        boundary_.t, boundary_.work, boundary_.friction, boundary_.damping, boundary_.radiated});
  checkpoint.PutShared("source_power/stretch", Flatten(stretch_));
  checkpoint.PutShared("source_power/recent", Flatten(recent_));
  checkpoint.PutShared("source_power/stretches", Flatten(stretches_));
  PetscFunctionReturn(0);
}

PetscErrorCode SourcePowerMeter::Restore(const store::Checkpoint& checkpoint) {
  PetscFunctionBeginUser;
  std::vector<double> v;
  PetscCall(checkpoint.GetShared("source_power/state", &v, 4));
  started_ = v[0] != 0.0, stopped_ = v[1] != 0.0, boundary_cycle_ = v[2], stretch_end_ = v[3];
  PetscCall(checkpoint.GetShared("source_power/accounts", &v, 10));
  previous_ = {v[0], v[1], v[2], v[3], v[4]};
  boundary_ = {v[5], v[6], v[7], v[8], v[9]};
  PetscCall(checkpoint.GetShared("source_power/stretch", &v));
  stretch_ = Unflatten(v);
  PetscCall(checkpoint.GetShared("source_power/recent", &v));
  recent_ = Unflatten(v);
  PetscCall(checkpoint.GetShared("source_power/stretches", &v));
  stretches_ = Unflatten(v);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

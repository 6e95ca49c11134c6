#include "vibrotherm/coupling/continuation/periodic_continuation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "vibrotherm/coupling/continuation/saved_wave_state.hpp"

namespace vibrotherm::coupling {

PeriodicContinuation::~PeriodicContinuation() {
  for (Vec& d : near_field_) VecDestroy(&d);
}

PetscErrorCode PeriodicContinuation::Setup(const ContinuationScene& scene, const mesh::Specimen& specimen,
                                           ContinuedWaves* waves, ContinuedHeat* heat, ContinuationObserver* observers,
                                           const std::string& dir, io::RunSummary* summary,
                                           const store::Checkpoint* resume) {
  PetscFunctionBeginUser;
  scene_ = scene;
  observers_ = observers;
  dir_ = dir;
  specimen_ = &specimen;
  waves_ = waves;
  heat_ = heat;
  period_ = 1.0 / scene.signal->frequency;
  heat_dt_ = scene.couple_dt / scene.heat_substeps;
  on_ = scene.periodic.on && waves && (heat || scene.periodic.choice == PeriodicChoice::On);
  if (!scene.periodic.on) note_ = "-periodic off (or the coupling cannot compare whole periods)";
  else if (!waves) note_ = "no waves";
  else if (!heat && scene.periodic.choice == PeriodicChoice::Auto) note_ = "-periodic auto: no heat runs";
  else if (heat && !heat->replayable()) {
    on_ = false;
    note_ = "a heat source cannot replay a recorded period (-thermoelastic)";
  }
  summary->derived["periodic_tol"] = scene.periodic.tol;
  if (!on_) PetscFunctionReturn(0);
  MPI_Comm comm = PetscObjectComm((PetscObject)waves->solver().space().dm());
  const double bytes = resume ? resume->Scalar("periodic/csv_bytes") : -1.0;
  PetscCall(detector_.Resume(comm, scene.periodic, dir + "/periodic.csv",
                             std::isnan(bytes) ? -1 : static_cast<long long>(bytes)));
  detector_.Attach(waves->solver().op().mass());
  PetscFunctionReturn(0);
}

bool PeriodicContinuation::AtPeriodBoundary(double t) const {
  const double k = t / period_;
  return std::abs(k - std::round(k)) < 1e-6;
}

PetscErrorCode PeriodicContinuation::AfterInterval(const io::EnergyRow& row, bool* ready) {
  PetscFunctionBeginUser;
  *ready = false;
  const double t = waves_ ? waves_->solver().time() : 0.0;
  if (!on_ || !AtPeriodBoundary(t)) PetscFunctionReturn(0);
  double start, end;
  const bool steady = scene_.signal->steady_stretch(t, &start, &end) && t < scene_.final_time;
  if (!steady || end == skip_stretch_) {
    if (phase_ == Phase::kRecord && heat_) PetscCall(heat_->StopRecording());
    phase_ = Phase::kWatch;
    detector_.Reset();
    outlook_.Reset();
    observers_->progress().SetOutlook(-1.0, 0, "");
    PetscFunctionReturn(0);
  }
  PetscInt multiple;
  PetscCall(detector_.Sample(*waves_, row, &multiple));
  PetscCall(Outlook(t, end));
  if (phase_ == Phase::kWatch && multiple > 0) PetscCall(StartRecording(t, multiple, row));
  else if (phase_ == Phase::kRecord && t >= record_end_ - 0.5 * heat_dt_) {
    if (multiple > 0 && multiple_ % multiple == 0) PetscCall(EndRecording(t, row, ready));
    else {  // it did not repeat after all: watch on
      if (heat_) PetscCall(heat_->StopRecording());
      phase_ = Phase::kWatch;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::Outlook(double t, double stretch_end) {
  PetscFunctionBeginUser;
  outlook_.Add(t / period_, detector_.last_change());
  const double change = outlook_.change(), tol = scene_.periodic.tol;
  if (!std::isfinite(change)) PetscFunctionReturn(0);  // the detector cannot compare whole windows yet
  const double to_go = outlook_.PeriodsToTolerance(tol), left = (stretch_end - t) / period_;
  char note[256];
  if (!outlook_.predictable()) {  // too few changes for a trend yet
    std::snprintf(note, sizeof(note), "periodic: change %.2g per period (tolerance %.2g)", change, tol);
    observers_->progress().SetOutlook(-1.0, 0, note);
    PetscFunctionReturn(0);
  }
  if (to_go < left) {
    const wave::WaveSolver& solver = waves_->solver();
    const double watch = to_go + detector_.window() + 1.0;  // then a window recorded, and compared once more
    const double resolved = watch * period_ / solver.step().dt() + TailSteps(stretch_end, outlook_.watched() + watch);
    std::snprintf(note, sizeof(note), "periodic: change %.2g per period (tolerance %.2g), ~%.0f periods to go", change,
                  tol, to_go);
    observers_->progress().SetOutlook(resolved, solver.steps(), note);
    PetscFunctionReturn(0);
  }
  std::snprintf(note, sizeof(note), "not periodic yet: change %.2g per period (tolerance %.2g)%s", change, tol,
                std::isfinite(to_go) ? ", shrinking too slowly for this stretch" : ", not shrinking");
  observers_->progress().SetOutlook(-1.0, 0, note);
  constexpr double kAdviseAfter = 100.0;  // periods watched before saying so
  if (outlook_.watched() < kAdviseAfter || advised_ == stretch_end) PetscFunctionReturn(0);
  advised_ = stretch_end;
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)waves_->solver().space().dm()),
                        "vibrotherm: note: not periodic after %.0f periods (t = %.6g s): the change per period is %.2g, "
                        "-periodic_tol %.2g, and %s; the waves are resolved to t = %.6g s unless it becomes periodic. "
                        "What may help: a looser -periodic_tol (1e-3 is about 1 %% in the thermosonic scene, "
                        "docs/MEASUREMENTS.md), -wave_start harmonic when damping builds the response up slowly, "
                        "-periodic_max_multiple when it repeats over more periods; periodic.csv has every period's "
                        "change\n",
                        outlook_.watched(), t, change, tol,
                        std::isfinite(to_go) ? "at its rate it would take longer than the stretch" : "it does not shrink",
                        stretch_end));
  PetscFunctionReturn(0);
}

double PeriodicContinuation::TailSteps(double stretch_end, double watched) const {
  const wave::SourceTimeFunction& signal = *scene_.signal;
  const double dt = waves_->solver().step().dt();
  double steps = std::max(0.0, scene_.waves_expected_end - stretch_end) / dt;
  for (const wave::SourceTimeFunction::Step& step : signal.schedule) {  // later stretches: watched as long, continued
    double start, end;
    if (step.t < stretch_end || !signal.steady_stretch(step.t + signal.blend_time() * (1 + 1e-9), &start, &end)) continue;
    const double continued = std::min(end, scene_.final_time) - start - watched * period_;
    if (continued > scene_.periodic.min_continued * period_) steps -= continued / dt;
  }
  return std::max(0.0, steps);
}

PetscErrorCode PeriodicContinuation::StartRecording(double t, PetscInt multiple, const io::EnergyRow& row) {
  PetscFunctionBeginUser;
  phase_ = Phase::kRecord;
  multiple_ = multiple * detector_.window();  // the window is recorded and replayed as one period
  record_start_ = t;
  record_end_ = t + multiple_ * period_;
  accumulated_start_ = waves_->Accumulated();
  row_start_ = row;
  if (heat_) PetscCall(heat_->StartRecording(t));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::EndRecording(double t, const io::EnergyRow& row,
                                                  bool* ready) {
  PetscFunctionBeginUser;
  phase_ = Phase::kWatch;
  if (heat_) PetscCall(heat_->StopRecording());
  double start, end;
  scene_.signal->steady_stretch(t, &start, &end);
  double stop = std::min(end, scene_.final_time);
  if (scene_.periodic.refresh > 0.0) stop = std::min(stop, t + scene_.periodic.refresh);
  const double P = RecordedPeriod();
  const PetscInt n = static_cast<PetscInt>(std::floor((stop - t) / P + 1e-9));
  if (n * multiple_ < scene_.periodic.min_continued) {  // not worth it: simulate the rest of this stretch
    skip_stretch_ = end;
    detector_.Reset();
    outlook_.Reset();
    PetscFunctionReturn(0);
  }
  double drift, error, projected;
  bool allows;
  PetscCall(DriftAllows(t, n, end, &drift, &error, &projected, &allows));
  if (!allows) {  // watch on: the drift and the periods left both shrink
    phase_ = Phase::kWatch;
    PetscFunctionReturn(0);
  }
  // What grows over the continuation: n times the recorded period's increase; the clock exactly n·P.
  const std::vector<double> now = waves_->Accumulated();
  increments_.resize(now.size());
  for (std::size_t i = 0; i < now.size(); ++i) increments_[i] = n * (now[i] - accumulated_start_[i]);
  increments_[0] = n * P;
  // A periodic state's source work is its losses (the window's small imbalance, a remnant of the
  // transient, would otherwise accumulate n-fold in the budget): this rank's share of them.
  // Layout (WaveSolver/CrackInterface::Accumulated): time, radiated, work, body work, damped, LTS
  // damped, then the crack's cells' W and its dissipated energy.
  const bool crack = waves_->crack() != nullptr;
  increments_[2] = increments_[1] - increments_[3] + increments_[4] + increments_[5] +
                   (crack ? increments_.back() : 0.0);
  row_end_ = row;
  segments_.push_back({record_start_, t, 0.0, multiple_, n, detector_.last_change(), drift, projected, error});
  pending_ = {t, n};
  *ready = true;
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::DriftAllows(double t, PetscInt n, double stretch_end, double* drift, double* error,
                                                 double* projected, bool* allows) {
  PetscFunctionBeginUser;
  // The period found: 1 in mean mode (whose window may have widened since the recording began).
  detector_.FrictionDrift(scene_.periodic.mean ? 1 : multiple_ / detector_.window(), drift, error);
  *projected = 0.5 * std::abs(*drift) * static_cast<double>(n * multiple_);
  const double tol = scene_.periodic.drift_tol;
  *allows = tol <= 0.0 || *projected <= tol || !Significant(*drift, *error);
  MPI_Comm comm = PetscObjectComm((PetscObject)waves_->solver().space().dm());
  if (!*allows && drift_said_ != stretch_end) {
    drift_said_ = stretch_end;
    PetscCall(PetscPrintf(comm,
                          "Periodic at t = %.6g s but the friction per period still drifts by %.2g (+-%.1g) per period: "
                          "continuing %" PetscInt_FMT " periods would be off by ~%.2g (-periodic_drift_tol %g); the "
                          "waves run on\n",
                          t, *drift, *error, n * multiple_, *projected, tol));
  } else if (*allows && WarnsOfDrift(*drift, *error, *projected)) {
    PetscCall(PetscPrintf(comm,
                          "Warning: the friction per period still drifts by %.2g (+-%.1g) per period; if that went on, "
                          "the %" PetscInt_FMT " periods continued would be off by ~%.2g (-periodic_drift_tol bounds it)\n",
                          *drift, *error, n * multiple_, *projected));
  }
  PetscFunctionReturn(0);
}

bool PeriodicContinuation::Significant(double drift, double error) { return std::abs(drift) > 2.0 * error; }

bool PeriodicContinuation::WarnsOfDrift(double drift, double error, double projected) const {
  return scene_.periodic.drift_tol <= 0.0 && projected > 10.0 * scene_.periodic.tol && Significant(drift, error);
}

PetscErrorCode PeriodicContinuation::Continue(bool* resumed) {
  PetscFunctionBeginUser;
  *resumed = false;
  const Pending pending = pending_;
  pending_ = {};
  if (pending.n > 0) PetscCall(ContinueFrom(pending.t2, pending.n, resumed));
  else PetscCall(FinishLadder(resumed));  // restarted inside the ladder
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::ContinueFrom(double t2, PetscInt n, bool* resumed) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)waves_->solver().space().dm());
  const double P = RecordedPeriod();
  ladder_.end = t2 + n * P;
  PetscCall(PetscPrintf(comm,
                        "Periodic at t = %.6g s (change %.2g): waves suspended, the heat continues with the recorded "
                        "%" PetscInt_FMT " periods (%.4g s) to t = %.6g s (x %" PetscInt_FMT ")\n",
                        t2, detector_.last_change(), multiple_, P, ladder_.end, n));
  kept_ = std::make_unique<store::Checkpoint>(comm);
  PetscCall(waves_->Snapshot(*specimen_, kept_.get()));
  if (!scene_.periodic.save_state.empty())
    PetscCall(SaveWaveState(scene_.periodic.save_state, *waves_, *specimen_, *scene_.excitation, t2));
  observers_->progress().Start(comm, "periodic", t2, ladder_.end, 0.0, true);  // heat steps from here, not wave steps
  if (heat_) {
    const PetscInt fine = std::min<PetscInt>(scene_.periodic.fine_periods, n);
    PetscCall(PhaseResolved(t2, fine, fine < n));
    ladder_.t = t2 + fine * P;
    ladder_.rung = P;  // whole recorded periods: every step ends on a period boundary (where D is exact)
    ladder_.count = 0;
    if (fine < n) {
      phase_ = Phase::kLadder;
      PetscCall(heat_->Replay(ReplayMode::Averaged));
      heat_->PauseNearField();
      PetscCall(AddNearField(ladder_.t, -1.0));  // the solver steps the smooth part θ − D
      PetscCall(heat_->solver().UseFreeIntegrator());
    }
  }
  PetscCall(FinishLadder(resumed));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::FinishLadder(bool* resumed) {
  PetscFunctionBeginUser;
  if (phase_ == Phase::kLadder) {
    heat_->PauseNearField();  // again after a restart inside the ladder (it holds no window there)
    bool stopped;
    PetscCall(Ladder(&stopped));
    if (stopped) PetscFunctionReturn(0);  // a signal: the checkpoint holds the ladder
    PetscCall(AddNearField(ladder_.end, 1.0));
    PetscCall(heat_->solver().UseCoupledIntegrator());
  }
  if (heat_) PetscCall(heat_->Replay(ReplayMode::Off));
  PetscCall(Resume());
  if (heat_) heat_->RestartNearField();
  phase_ = Phase::kWatch;
  detector_.Reset();
  outlook_.Reset();
  *resumed = true;
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::Resume() {
  PetscFunctionBeginUser;
  // The waves from the kept state, n periods on: everything that grows grows n times the period's increase.
  PetscCall(waves_->ResumeFrom(*kept_, *specimen_, increments_));
  kept_.reset();
  segments_.back().resumed = waves_->solver().time();
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)waves_->solver().space().dm()), "Waves resumed at t = %.6g s\n",
                        waves_->solver().time()));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::PhaseResolved(double t2, PetscInt periods, bool twin) {
  PetscFunctionBeginUser;
  const PetscInt per_period = static_cast<PetscInt>(std::lround(RecordedPeriod() / heat_dt_));
  const PetscInt steps = periods * per_period, substeps = scene_.heat_substeps;
  const auto time = [&](PetscInt j) { return t2 + static_cast<double>(j) * heat_dt_; };
  store::Checkpoint before(PetscObjectComm((PetscObject)heat_->solver().space().dm()));
  if (twin) PetscCall(heat_->SolverSnapshot(*specimen_, &before));
  PetscCall(heat_->Replay(ReplayMode::PhaseLocked));
  for (Vec& d : near_field_) PetscCall(VecDestroy(&d));
  near_field_.assign(twin ? per_period : 0, nullptr);
  for (PetscInt j = 1; j <= steps; ++j) {
    PetscCall(heat_->StepTo(time(j)));
    PetscCall(Observe(time(j), j % substeps == 0));
    const PetscInt k = j - (steps - per_period);  // 1..per_period over the last period: phase k (per_period ≡ 0)
    if (twin && k >= 1) {
      Vec& d = near_field_[k % per_period];
      PetscCall(VecDuplicate(heat_->solver().rise(), &d));
      PetscCall(VecCopy(heat_->solver().rise(), d));
    }
  }
  if (!twin) PetscFunctionReturn(0);
  // The averaged twin from the same state: D = phase-locked − averaged, by phase.
  store::Checkpoint after(PetscObjectComm((PetscObject)heat_->solver().space().dm()));
  PetscCall(heat_->SolverSnapshot(*specimen_, &after));
  PetscCall(heat_->RestoreSolver(before, *specimen_));
  for (PetscInt j = 1; j <= steps; ++j) {
    PetscCall(heat_->StepAveraged(time(j)));
    const PetscInt k = j - (steps - per_period);
    if (k >= 1) PetscCall(VecAXPY(near_field_[k % per_period], -1.0, heat_->solver().rise()));
  }
  PetscCall(heat_->RestoreSolver(after, *specimen_));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::AddNearField(double t, double sign) {
  PetscFunctionBeginUser;
  if (near_field_.empty()) PetscFunctionReturn(0);
  const double P = RecordedPeriod(), phase = std::fmod(t - record_end_, P);
  const double x = (phase < 0.0 ? phase + P : phase) / heat_dt_;
  const PetscInt count = static_cast<PetscInt>(near_field_.size());
  const PetscInt lo = static_cast<PetscInt>(std::floor(x + 1e-9)) % count, hi = (lo + 1) % count;
  const double w = std::clamp(x - std::floor(x + 1e-9), 0.0, 1.0);
  Vec rise = heat_->solver().rise();
  PetscCall(VecAXPY(rise, sign * (1.0 - w), near_field_[lo]));
  if (w > 1e-9) PetscCall(VecAXPY(rise, sign * w, near_field_[hi]));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::Ladder(bool* stopped) {
  PetscFunctionBeginUser;
  *stopped = false;
  MPI_Comm comm = PetscObjectComm((PetscObject)heat_->solver().space().dm());
  observers_->progress().Start(comm, "periodic", ladder_.t, ladder_.end, 0.0, true);
  while (ladder_.t < ladder_.end * (1 - 1e-12)) {
    const double next = std::min(ladder_.t + ladder_.rung, observers_->NextHeatStop(ladder_.t, ladder_.end));
    PetscCall(heat_->StepTo(next, false));
    ladder_.t = next;
    PetscCall(AddNearField(ladder_.t, 1.0));  // the probes sample θ (their own near field is the crack's)
    PetscCall(heat_->SampleProbes());
    PetscCall(Observe(ladder_.t, true));
    PetscCall(AddNearField(ladder_.t, -1.0));
    if (++ladder_.count % scene_.periodic.ladder_steps == 0) ladder_.rung *= 2.0;
    PetscCall(observers_->BetweenSteps(stopped));
    if (*stopped) PetscFunctionReturn(0);
  }
  PetscCall(observers_->progress().Done(ladder_.t, heat_->solver().steps()));
  PetscFunctionReturn(0);
}

io::EnergyRow PeriodicContinuation::WaveRow(double t) const {
  io::EnergyRow row = row_end_;
  const double growth = (t - record_end_) / (record_end_ - record_start_);
  for (double io::EnergyRow::*column : {&io::EnergyRow::radiated, &io::EnergyRow::dissipated, &io::EnergyRow::damped,
                                        &io::EnergyRow::work_thermal})
    row.*column += growth * (row_end_.*column - row_start_.*column);
  // The source works what the losses take (as the waves' accounts on resume).
  row.work_source = row_end_.work_source + (row.radiated - row_end_.radiated) + (row.dissipated - row_end_.dissipated) +
                    (row.damped - row_end_.damped) - (row.work_thermal - row_end_.work_thermal);
  row.t = t;
  return row;
}

PetscErrorCode PeriodicContinuation::Observe(double t, bool interval) {
  PetscFunctionBeginUser;
  const io::EnergyRow row = interval ? WaveRow(t) : io::EnergyRow{};
  PetscCall(observers_->HeatStepContinued(t, interval ? &row : nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicContinuation::Finish(io::RunSummary* summary) {
  PetscFunctionBeginUser;
  if (on_) PetscCall(detector_.Finish());
  if (specimen_ && !scene_.periodic.save_state.empty() && segments_.empty())
    PetscCall(PetscPrintf(PetscObjectComm((PetscObject)specimen_->wave),
                          "vibrotherm: note: -periodic_save_state %s: nothing saved, the waves were never suspended (%s)\n",
                          scene_.periodic.save_state.c_str(), on_ ? "never periodic" : note_.c_str()));
  summary->derived["periodic_segments"] = static_cast<double>(segments_.size());
  PetscInt continued = 0;
  for (const Segment& s : segments_) continued += s.periods * s.multiple;
  summary->derived["periodic_periods_continued"] = static_cast<double>(continued);
  if (!segments_.empty()) summary->derived["periodic_reached_at"] = segments_.front().detected;
  summary->derived["periodic_last_change"] = detector_.last_change();
  double projected = 0.0, warned = 0.0;  // the largest projection, and the largest warned about
  for (const Segment& s : segments_) {
    projected = std::max(projected, s.projected);
    if (WarnsOfDrift(s.drift, s.drift_error, s.projected)) warned = std::max(warned, s.projected);
  }
  summary->derived["periodic_drift_projected"] = projected;
  if (warned > 0.0) {
    char text[256];
    std::snprintf(text, sizeof(text), "the friction per period still drifted when the continuation froze it: the "
                  "continued heat may be off by ~%.2g (periodic[].drift_projected; -periodic_drift_tol bounds it)",
                  warned);
    summary->warnings.push_back(text);
  }
  summary->derived_rules["periodic"] = on_ ? (segments_.empty() ? "on: never periodic within -periodic_tol" : "on")
                                           : "off: " + note_;
  summary->periodic.clear();
  for (const Segment& s : segments_)
    summary->periodic.push_back({s.detected, s.suspended, s.resumed, static_cast<double>(s.multiple),
                                 static_cast<double>(s.periods * s.multiple), s.change, s.drift, s.projected});
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

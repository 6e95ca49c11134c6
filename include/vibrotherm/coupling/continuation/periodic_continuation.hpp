// Periodic continuation of the coupled wave–contact system (issue 24).
//
// A real thermosonic test excites for 0.1–10 s; after its transients the scene
// repeats itself period after period. So, within a steady stretch of the source
// (constant amplitude; excitation.hpp):
//   watch     at every source-period boundary the detector (periodic_detector.hpp)
//             compares the state with the last periods; once the run repeats with
//             a period of m source periods (P = m/f) ...
//   record    ... the waves run one more P while the heat sources record what
//             they deposit (per contact cell, per heat step); if the run still
//             repeats, the wave state at the end is kept in memory and the waves
//             are suspended ...
//   continue  ... for the n whole periods the source stays the same (to its next
//             change, -final_time, or -periodic_refresh). The heat receives the
//             recorded period: first -periodic_fine_periods periods phase-locked
//             at the coupled heat step (exactly what the full run would receive),
//             then on a step ladder (-periodic_ladder_steps steps per rung, the
//             step doubling) with the period's average power. The near field of
//             the crack's heat pulses, which the average lacks, is added back as
//             D(φ) = θ(phase-locked) − θ(averaged) over the last fine period (a
//             twin run of the heat from the same state): by linearity the exact
//             periodic part, up to a transient that decays as t^-1/2.
//   resume    then the waves restart from the kept state at the same phase,
//             jumped ahead by n·P (their clock, the source's work, the radiated,
//             dissipated and damped energy, every cell's W: n times the recorded
//             period's increase), and the heat goes on coupled: the ramp-down, a
//             schedule step, or the next refresh is simulated in full.
// Probes (temperature), field outputs, camera frames and energy.csv go on with
// the right time stamps (wave columns of energy.csv: the recorded period's
// accounts, growing linearly).
#pragma once

#include <petscvec.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/coupling/continuation/continued_parts.hpp"
#include "vibrotherm/coupling/continuation/periodic_detector.hpp"
#include "vibrotherm/coupling/continuation/periodic_outlook.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::coupling {

class PeriodicContinuation {
 public:
  PeriodicContinuation() = default;
  PeriodicContinuation(const PeriodicContinuation&) = delete;
  PeriodicContinuation& operator=(const PeriodicContinuation&) = delete;
  ~PeriodicContinuation();

  /// Whether this scene can use it (-periodic on, waves, every heat source replayable); says why not.
  /// observers: the run's, told of every heat step the continuation takes without waves.
  /// resume: continue the files of the interrupted run whose checkpoint it is.
  PetscErrorCode Setup(const ContinuationScene& scene, const mesh::Specimen& specimen, ContinuedWaves* waves,
                       ContinuedHeat* heat, ContinuationObserver* observers, const std::string& dir,
                       io::RunSummary* summary, const store::Checkpoint* resume = nullptr);
  bool on() const { return on_; }
  /// After a coupling interval of the waves (energy row `row` at its end): watch and record as
  /// above; *ready once the recorded period can be continued (Continue is the run's next phase).
  PetscErrorCode AfterInterval(const io::EnergyRow& row, bool* ready);
  /// A continuation is ready: found by AfterInterval, or restarted inside its heat ladder.
  bool ready() const { return pending_.n > 0 || phase_ == Phase::kLadder; }
  /// The continued phase: the heat for the n periods the source stays the same (or the rest of
  /// the ladder after a restart), then the waves resumed (*resumed; false: a signal stopped it).
  PetscErrorCode Continue(bool* resumed);
  /// Fills summary.json's "periodic" and publishes periodic.csv (a complete run).
  PetscErrorCode Finish(io::RunSummary* summary);
  void Keep() { detector_.Keep(); }
  /// Checkpoints (periodic_state.cpp): the detector's samples, a recording under way, a
  /// continuation's ladder; and back (after the components).
  PetscErrorCode Save(store::Checkpoint& checkpoint) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint);

 private:
  enum class Phase { kWatch, kRecord, kLadder };
  bool AtPeriodBoundary(double t) const;
  /// The progress line's outlook while watching (issue 43): the change per period against the
  /// tolerance, the periods its trend still needs, the steps the run then resolves; once per
  /// stretch, when the change does not shrink toward the tolerance in time, what would help.
  PetscErrorCode Outlook(double t, double stretch_end);
  /// Wave steps resolved after the steady stretch ending at stretch_end: to the waves' expected
  /// end, less what later stretches continue when each is watched `watched` periods.
  double TailSteps(double stretch_end, double watched) const;
  PetscErrorCode StartRecording(double t, PetscInt multiple, const io::EnergyRow& row);
  PetscErrorCode EndRecording(double t, const io::EnergyRow& row, bool* ready);
  /// Whether the friction's drift (measured over the detector's samples) allows continuing n
  /// recorded periods (a drift that is not Significant allows it); says so once per steady
  /// stretch when it does not. *drift, *error, *projected: as Segment.
  PetscErrorCode DriftAllows(double t, PetscInt n, double stretch_end, double* drift, double* error, double* projected,
                             bool* allows);
  /// A continuation that froze a drift costing more than 10 -periodic_tol is warned about
  /// (console and summary), unless -periodic_drift_tol bounded it or the drift is within two
  /// standard errors of none (a scatter's slope is not a drift).
  bool WarnsOfDrift(double drift, double error, double projected) const;
  /// A drift beyond two standard errors of none (within them it is the scatter's slope).
  static bool Significant(double drift, double error);
  /// n whole periods of heat without waves from t2, then the waves resumed n·P later.
  PetscErrorCode ContinueFrom(double t2, PetscInt n, bool* resumed);
  /// The rest of the heat ladder (after a restart inside it: from its checkpoint), then the waves resumed.
  PetscErrorCode FinishLadder(bool* resumed);
  /// The phase-resolved start: `periods` periods of heat steps with the recorded power;
  /// with `twin`, the averaged twin from the same state gives D over the last period.
  PetscErrorCode PhaseResolved(double t2, PetscInt periods, bool twin);
  /// The ladder with the averaged power from ladder_.t to ladder_.end (a period boundary); stops early on a signal.
  PetscErrorCode Ladder(bool* stopped);
  /// The waves from the kept state at ladder_.end, jumped ahead.
  PetscErrorCode Resume();
  /// The records of a heat step at t without waves (interval rows when `interval`).
  PetscErrorCode Observe(double t, bool interval);
  /// energy.csv's wave columns at t during the continuation: the recorded period's growth.
  io::EnergyRow WaveRow(double t) const;
  /// θ += sign · D at the phase of t.
  PetscErrorCode AddNearField(double t, double sign);
  double RecordedPeriod() const { return multiple_ * period_; }

  bool on_ = false;
  ContinuationScene scene_;
  const mesh::Specimen* specimen_ = nullptr;
  ContinuedWaves* waves_ = nullptr;
  ContinuedHeat* heat_ = nullptr;
  ContinuationObserver* observers_ = nullptr;
  std::string dir_;
  PeriodicDetector detector_;
  Phase phase_ = Phase::kWatch;
  double period_ = 0.0;       ///< the source's
  double heat_dt_ = 0.0;      ///< the coupled heat step
  PetscInt multiple_ = 0;     ///< source periods in the period recorded and replayed (the found one × the window)
  double record_start_ = 0.0, record_end_ = 0.0;
  double skip_stretch_ = -1.0;  ///< end of a steady stretch too short to continue (watch no more in it)
  double drift_said_ = -1.0;    ///< end of the steady stretch whose drift held the waves on (said once)
  PeriodicOutlook outlook_;     ///< the change per period's trend: the progress line's ETA
  double advised_ = -1.0;       ///< end of the steady stretch whose slow periodicity was said (once)
  std::vector<double> accumulated_start_;  ///< the waves' growing accounts at the recording's start (this rank)
  std::vector<double> increments_;         ///< what they grow by over the continuation
  io::EnergyRow row_start_, row_end_;
  std::unique_ptr<store::Checkpoint> kept_;  ///< the waves at the recording's end
  std::vector<Vec> near_field_;           ///< D at each heat step of the last recorded period (index 0: phase 0)
  struct Pending {  ///< a continuation found, not yet run: from t2, n recorded periods
    double t2 = 0.0;
    PetscInt n = 0;
  } pending_;
  struct LadderState {
    double t = 0.0, end = 0.0, rung = 0.0;
    PetscInt count = 0;
  } ladder_;
  struct Segment {
    double detected, suspended, resumed;
    PetscInt multiple, periods;
    double change;
    double drift, projected;  ///< the friction's relative drift per source period; half of it over the periods
    double drift_error;       ///< the drift's standard error (its fit's)
  };
  std::vector<Segment> segments_;
  std::string note_;  ///< why it is off
};

}  // namespace vibrotherm::coupling

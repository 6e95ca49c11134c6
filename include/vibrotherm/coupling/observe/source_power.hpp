// The power the source puts in and where it goes (the thermosonic efficiency).
// From the energy columns at every coupling interval's end while the waves run (or a
// continuation replays them), the cumulative accounts
// (the source's work, the crack's friction, material damping, radiation) at every
// source-period boundary (the source's cycles: a sweep's too) give each period's
// mean powers, written to source_power.csv. A boundary between two rows takes the
// accounts interpolated linearly between them: exact where the rows land on the
// boundaries (a periodic continuation: the steps are quantized so that the coupling
// intervals divide its period, coupling/run/scene.cpp), within a wave step's exchange
// otherwise (no continuation, -wave_dt, a sweep's moving period). A lightly
// damped specimen's source power swings far above its mean within a period, so only
// whole periods mean anything.
//
// The summary's figures (summary.json source_power, input_power, friction_power,
// thermosonic_efficiency) are each steady stretch's last `window` periods before the
// source changed (its switch-off, a schedule step): the periodic state the run
// reached, or the state a continuation replayed. A run with no steady stretch (a
// sweep, or one too short to reach it) reports its last `window` periods, flagged
// not steady.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/io/source_power_log.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/wave/excitation.hpp"

namespace vibrotherm::coupling {

class SourcePowerMeter {
 public:
  /// Opens path (source_power.csv); resume: continue the interrupted run whose checkpoint it is. Collective.
  PetscErrorCode Open(MPI_Comm comm, const wave::SourceTimeFunction& signal, PetscInt window, const std::string& path,
                      const store::Checkpoint* resume = nullptr);
  bool open() const { return log_.open(); }
  /// Every energy row while the waves run (wave columns: source work, dissipated, damped, radiated).
  void OnEnergyRow(const io::EnergyRow& row);
  /// The waves stopped: later rows carry their frozen columns.
  void Stop() { stopped_ = true; }
  /// The periods' figures into the summary and on the console; publishes source_power.csv. Collective.
  PetscErrorCode Finish(io::RunSummary* summary);
  /// Checkpoints (source_power_state in the recorder's): the accounts at the last row and
  /// boundary, the stretches' last periods, the file's length; and back (Open does, given the checkpoint).
  PetscErrorCode Save(store::Checkpoint& checkpoint) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint);
  void Keep() { log_.Keep(); }

 private:
  /// The cumulative accounts at time t.
  struct Accounts {
    double t = 0.0, work = 0.0, friction = 0.0, damping = 0.0, radiated = 0.0;
  };
  static Accounts From(const io::EnergyRow& row) { return {row.t, row.work_source, row.dissipated, row.damped, row.radiated}; }
  static Accounts Interpolate(const Accounts& a, const Accounts& b, double t);
  /// The mean powers between two boundaries `periods` periods apart.
  io::SourcePowerRow Between(const Accounts& from, const Accounts& to, double periods) const;
  /// Written, and kept for the summary by the steady stretch it lies in.
  void Close(const io::SourcePowerRow& row);
  /// The rows' totals over their last `window_` periods (or all of them, when fewer).
  io::SourcePowerRow LastPeriods(const std::vector<io::SourcePowerRow>& rows) const;
  /// Keeps the fewest newest rows that still span `window_` periods.
  void Trim(std::vector<io::SourcePowerRow>* rows) const;

  MPI_Comm comm_ = MPI_COMM_NULL;
  const wave::SourceTimeFunction* signal_ = nullptr;
  double window_ = 4.0;
  io::SourcePowerLog log_;
  bool stopped_ = false, started_ = false;
  Accounts previous_, boundary_;  ///< at the last row; at the last period boundary passed
  double boundary_cycle_ = 0.0;   ///< that boundary's cycle number
  double stretch_end_ = -1.0;     ///< the steady stretch the rows of `stretch_` lie in (its end)
  std::vector<io::SourcePowerRow> stretch_, recent_;  ///< that stretch's last periods; the last periods of any kind
  std::vector<io::SourcePowerRow> stretches_;         ///< each finished stretch's last periods
};

}  // namespace vibrotherm::coupling

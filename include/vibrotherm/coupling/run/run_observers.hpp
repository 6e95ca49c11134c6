// The run's observers, registered once (Simulation::Run): the recorder (probes, energy rows,
// crack state, field outputs, the field's peak, the IR camera, the progress line) and the
// checkpoints between steps. Every phase of a run — coupled, continued (continuation/), heat
// alone — tells them of its steps here, once per wave step, heat step and coupling interval;
// no phase writes a record itself. The order of the records within a step lives here only.
#pragma once

#include <functional>

#include "vibrotherm/coupling/continuation/continued_parts.hpp"
#include "vibrotherm/coupling/observe/recorder.hpp"
#include "vibrotherm/coupling/run/heat_component.hpp"
#include "vibrotherm/coupling/run/wave_component.hpp"

namespace vibrotherm::coupling {

/// What the waves do while a heat step or an interval is recorded.
enum class WavesNow {
  kCoupled,    ///< they run and feed the heat (or run without heat)
  kContinued,  ///< suspended by a continuation: their columns grow as the recorded period's
  kStopped     ///< quiet and freed: their columns stay as they were at the stop
};

class RunObservers final : public ContinuationObserver {
 public:
  /// waves, heat: the run's components (null: not in this scene). probe_every: -probe_every
  /// (the heat samples the probes' temperatures at the wave steps that have a probe row).
  RunObservers(Recorder& recorder, const WaveComponent* waves, HeatComponent* heat, PetscInt probe_every);
  /// The checkpoint observer: between a continuation's heat steps, a checkpoint when due
  /// (*stop: a signal stops the run). Registered once by the run, which owns the checkpoints.
  void OnBetweenSteps(std::function<PetscErrorCode(bool* stop)> between) { between_ = std::move(between); }
  /// t = 0 of a run that does not restart: the first records (waves: their energy row at 0).
  PetscErrorCode Start(const io::EnergyRow* waves);
  /// After every accepted wave step.
  PetscErrorCode WaveStep(const wave::WaveSolver& w);
  /// After every heat step while the waves run (within a coupling interval).
  PetscErrorCode HeatStepCoupled(const heat::HeatSolver& heat);
  /// The end of a coupling interval while the waves run (their energy row then).
  PetscErrorCode IntervalCoupled(const io::EnergyRow& row) { return IntervalRecords(row.t, row, WavesNow::kCoupled); }
  PetscErrorCode HeatStepContinued(double t, const io::EnergyRow* interval) override;
  /// After every heat step of the heat running alone (every one ends an interval).
  PetscErrorCode HeatStepAlone(const heat::HeatSolver& heat);
  /// Where the heat running alone starts: the field output due there.
  PetscErrorCode HeatAloneStart(double t) { return FieldsIfDue(t, WavesNow::kStopped); }
  /// The waves stopped (`last`: their final energy row).
  PetscErrorCode WavesStopped(const io::EnergyRow& last);
  PetscErrorCode BetweenSteps(bool* stop) override;
  double NextHeatStop(double t, double end) const override { return recorder_.NextHeatStop(t, end); }
  io::Progress& progress() override { return recorder_.progress(); }
  /// The recorder they notify (a checkpoint saves its state).
  Recorder& recorder() { return recorder_; }
  /// Restores the recorder after the components (it replays the field outputs' index).
  PetscErrorCode Restore(const store::Checkpoint& checkpoint);

 private:
  /// The records of an interval ending at t: temperatures, the source's power, energy, fields.
  PetscErrorCode IntervalRecords(double t, const io::EnergyRow& row, WavesNow waves);
  /// The probes' temperatures the heat holds since the last call.
  PetscErrorCode RecordTemperature(bool waves_running);
  /// An energy row: the wave columns of `row`, and (heat running) the heat's time and columns.
  PetscErrorCode RecordEnergy(io::EnergyRow row);
  /// The field outputs due at t, of the components that run.
  PetscErrorCode FieldsIfDue(double t, WavesNow waves);

  Recorder& recorder_;
  const WaveComponent* waves_;
  HeatComponent* heat_;
  PetscInt probe_every_;
  std::function<PetscErrorCode(bool* stop)> between_;
};

}  // namespace vibrotherm::coupling

#include "vibrotherm/coupling/run/run_observers.hpp"

namespace vibrotherm::coupling {

RunObservers::RunObservers(Recorder& recorder, const WaveComponent* waves, HeatComponent* heat, PetscInt probe_every)
    : recorder_(recorder), waves_(waves), heat_(heat), probe_every_(probe_every) {}

PetscErrorCode RunObservers::Start(const io::EnergyRow* waves) {
  PetscFunctionBeginUser;
  if (heat_) {
    PetscCall(RecordTemperature(waves != nullptr));
    PetscCall(recorder_.OnHeatStep(heat_->solver()));
  }
  if (!waves) PetscFunctionReturn(0);
  recorder_.OnInterval(*waves);
  PetscCall(RecordEnergy(*waves));
  PetscCall(FieldsIfDue(0.0, WavesNow::kCoupled));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::WaveStep(const wave::WaveSolver& w) {
  PetscFunctionBeginUser;
  // The heat side samples the friction at every wave step, the probes' temperatures at their rows.
  if (heat_) heat_->AfterWaveStep(w.time(), w.steps() % probe_every_ == 0);
  // With heat, energy rows come at intervals (every column known at one time), else every -energy_every steps.
  PetscCall(recorder_.OnWaveStep(w, heat_ == nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::HeatStepCoupled(const heat::HeatSolver& heat) {
  PetscFunctionBeginUser;
  PetscCall(recorder_.OnHeatStep(heat));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::HeatStepContinued(double t, const io::EnergyRow* interval) {
  PetscFunctionBeginUser;
  PetscCall(recorder_.OnHeatStep(heat_->solver()));
  if (interval) PetscCall(IntervalRecords(t, *interval, WavesNow::kContinued));
  else PetscCall(FieldsIfDue(t, WavesNow::kContinued));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::HeatStepAlone(const heat::HeatSolver& heat) {
  PetscFunctionBeginUser;
  PetscCall(recorder_.OnHeatStep(heat));
  PetscCall(IntervalRecords(heat.time(), recorder_.waves_at_stop(), WavesNow::kStopped));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::WavesStopped(const io::EnergyRow& last) {
  PetscFunctionBeginUser;
  if (!heat_) PetscCall(RecordEnergy(last));
  recorder_.FlushProbes();
  recorder_.StopWaves(last);
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::BetweenSteps(bool* stop) {
  PetscFunctionBeginUser;
  *stop = false;
  if (between_) PetscCall(between_(stop));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::Restore(const store::Checkpoint& checkpoint) {
  PetscFunctionBeginUser;
  PetscCall(recorder_.Restore(checkpoint, waves_ ? &waves_->solver() : nullptr, heat_ ? &heat_->solver() : nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::IntervalRecords(double t, const io::EnergyRow& row, WavesNow waves) {
  PetscFunctionBeginUser;
  switch (waves) {
    case WavesNow::kCoupled:
      recorder_.OnInterval(row);
      if (heat_) {
        PetscCall(RecordTemperature(true));
        PetscCall(RecordEnergy(row));
      } else {
        recorder_.FlushProbes();  // energy rows came with the wave steps
      }
      break;
    case WavesNow::kContinued:
    case WavesNow::kStopped:
      PetscCall(RecordTemperature(false));
      if (waves == WavesNow::kContinued) recorder_.OnInterval(row);  // the source still works
      PetscCall(RecordEnergy(row));
      PetscCall(recorder_.progress().Update(t, heat_->solver().steps()));  // heat steps set the pace now
      break;
  }
  PetscCall(FieldsIfDue(t, waves));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::RecordTemperature(bool waves_running) {
  PetscFunctionBeginUser;
  io::TemperatureSeries series;
  PetscCall(heat_->ProbeSeries(&series));
  PetscCall(recorder_.RecordTemperature(series, heat_->solver().material().T0, waves_running));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::RecordEnergy(io::EnergyRow row) {
  PetscFunctionBeginUser;
  if (heat_) {
    row.t = heat_->solver().time();
    PetscCall(heat_->Energy(&row));
  }
  PetscCall(recorder_.RecordEnergy(row));
  PetscFunctionReturn(0);
}

PetscErrorCode RunObservers::FieldsIfDue(double t, WavesNow waves) {
  PetscFunctionBeginUser;
  if (!recorder_.OutputDue(t)) PetscFunctionReturn(0);
  const bool with_waves = waves == WavesNow::kCoupled && waves_;
  PetscCall(recorder_.WriteFields(t, with_waves ? &waves_->solver() : nullptr, heat_ ? &heat_->solver() : nullptr));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

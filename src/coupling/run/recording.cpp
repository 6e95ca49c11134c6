#include "vibrotherm/coupling/run/recording.hpp"

namespace vibrotherm::coupling {

PetscErrorCode RecordEnergy(Recorder& recorder, io::EnergyRow row, const HeatComponent* heat) {
  PetscFunctionBeginUser;
  if (heat) {
    row.t = heat->solver().time();
    PetscCall(heat->Energy(&row));
  }
  PetscCall(recorder.RecordEnergy(row));
  PetscFunctionReturn(0);
}

PetscErrorCode RecordTemperature(Recorder& recorder, HeatComponent& heat, bool waves_running) {
  PetscFunctionBeginUser;
  io::TemperatureSeries series;
  PetscCall(heat.ProbeSeries(&series));
  PetscCall(recorder.RecordTemperature(series, heat.solver().material().T0, waves_running));
  PetscFunctionReturn(0);
}

PetscErrorCode WriteFields(Recorder& recorder, double t, const WaveComponent* waves, const HeatComponent* heat) {
  PetscFunctionBeginUser;
  PetscCall(recorder.WriteFields(t, waves ? &waves->solver() : nullptr, heat ? &heat->solver() : nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode RestoreRecorder(Recorder& recorder, const store::Checkpoint& checkpoint, const WaveComponent* waves,
                               const HeatComponent* heat) {
  PetscFunctionBeginUser;
  PetscCall(recorder.Restore(checkpoint, waves ? &waves->solver() : nullptr, heat ? &heat->solver() : nullptr));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

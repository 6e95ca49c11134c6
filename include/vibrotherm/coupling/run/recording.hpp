// The run's side of recording: the recorder (observe/) reads solvers and rows;
// these fill them from the run's components (the heat's columns of an energy row,
// the probes' temperature series, the solvers behind the field outputs).
#pragma once

#include "vibrotherm/coupling/observe/recorder.hpp"
#include "vibrotherm/coupling/run/heat_component.hpp"
#include "vibrotherm/coupling/run/wave_component.hpp"

namespace vibrotherm::coupling {

/// Appends an energy row: the wave columns of `row`, and (heat running) the heat's time and columns.
PetscErrorCode RecordEnergy(Recorder& recorder, io::EnergyRow row, const HeatComponent* heat);
/// The probes' temperatures the heat holds since the last call.
PetscErrorCode RecordTemperature(Recorder& recorder, HeatComponent& heat, bool waves_running);
/// The field outputs of the components that run (null: not running).
PetscErrorCode WriteFields(Recorder& recorder, double t, const WaveComponent* waves, const HeatComponent* heat);
/// Restores the recorder after the components (it replays the field outputs' index).
PetscErrorCode RestoreRecorder(Recorder& recorder, const store::Checkpoint& checkpoint, const WaveComponent* waves,
                               const HeatComponent* heat);

}  // namespace vibrotherm::coupling

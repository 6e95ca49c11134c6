#include "vibrotherm/coupling/observe/wave_energy_row.hpp"

namespace vibrotherm::coupling {

PetscErrorCode WaveEnergyRow(const wave::WaveSolver& solver, io::EnergyRow* row) {
  PetscFunctionBeginUser;
  wave::WaveEnergy e;
  PetscCall(solver.Energy(&e));
  row->t = solver.time();
  row->work_source = e.work_source;
  row->kinetic = e.kinetic;
  row->strain = e.strain;
  row->radiated = e.radiated;
  row->integrator_correction = e.integrator;
  row->interface_stored = e.interface_stored;
  row->dissipated = e.dissipated;
  row->work_thermal = e.work_body;  // the only body force: the two-way thermal stress
  row->damped = e.damped;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

#include "vibrotherm/coupling/continuation/saved_wave_state.hpp"

#include <cmath>

namespace vibrotherm::coupling {

namespace {

double SourceKind(const wave::Excitation& e) {
  return 2.0 * static_cast<double>(e.type) + static_cast<double>(e.component);
}

PetscErrorCode GlobalDofs(const wave::WaveSolver& solver, PetscInt* n) {
  PetscFunctionBeginUser;
  PetscCall(VecGetSize(solver.op().mass(), n));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode SaveWaveState(const std::string& path, const ContinuedWaves& waves, const mesh::Specimen& specimen,
                             const wave::Excitation& excitation, double t) {
  PetscFunctionBeginUser;
  store::Checkpoint state(PetscObjectComm((PetscObject)waves.solver().space().dm()));
  PetscCall(waves.Snapshot(specimen, &state));
  PetscInt dofs;
  PetscCall(GlobalDofs(waves.solver(), &dofs));
  state.PutShared("source/frequency", {excitation.signal.frequency});
  state.PutShared("source/amplitude", {excitation.signal.envelope(t)});
  state.PutShared("source/kind", {SourceKind(excitation)});
  state.PutShared("source/saved_at", {t});
  state.PutShared("wave/dofs", {static_cast<double>(dofs)});
  PetscCall(state.Write(path));
  PetscFunctionReturn(0);
}

PetscErrorCode StartFromSavedState(const std::string& path, const mesh::Specimen& specimen,
                                   const wave::Excitation& excitation, wave::WaveSolver* solver) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)solver->space().dm());
  store::Checkpoint state(comm);
  PetscCall(state.Read(path, "-wave_start_state"));
  std::vector<double> frequency, amplitude, kind, saved_at, dofs;
  PetscCall(state.GetShared("source/frequency", &frequency, 1));
  PetscCall(state.GetShared("source/amplitude", &amplitude, 1));
  PetscCall(state.GetShared("source/kind", &kind, 1));
  PetscCall(state.GetShared("source/saved_at", &saved_at, 1));
  PetscCall(state.GetShared("wave/dofs", &dofs, 1));
  PetscInt n;
  PetscCall(GlobalDofs(*solver, &n));
  PetscCheck(dofs[0] == static_cast<double>(n), comm, PETSC_ERR_USER_INPUT,
             "-wave_start_state %s: saved on a mesh of %.0f wave dofs, this run has %" PetscInt_FMT, path.c_str(),
             dofs[0], n);
  const wave::SourceTimeFunction& signal = excitation.signal;
  PetscCheck(std::abs(frequency[0] / signal.frequency - 1.0) < 1e-12, comm, PETSC_ERR_USER_INPUT,
             "-wave_start_state %s: saved at -source_frequency %.12g Hz, this run's is %.12g Hz (a state fits only "
             "its own frequency)",
             path.c_str(), frequency[0], signal.frequency);
  PetscCheck(kind[0] == SourceKind(excitation), comm, PETSC_ERR_USER_INPUT,
             "-wave_start_state %s: saved with another -source_type or -source_component", path.c_str());
  PetscCheck(amplitude[0] > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-wave_start_state %s: saved while the source was off (amplitude %g)", path.c_str(), amplitude[0]);
  const double start = signal.envelope(1e-6 / signal.frequency);  // just after t = 0 (the window is 0 at 0 itself)
  const double scale = start / amplitude[0];
  PetscCall(solver->StartFromState(state, specimen.wave_origin, scale));
  PetscCall(PetscPrintf(comm, "Waves start in the state of %s (saved at t = %.6g s, scaled by %.6g to amplitude %g)\n",
                        path.c_str(), saved_at[0], scale, start));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

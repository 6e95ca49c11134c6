#include "vibrotherm/coupling/exchange/damping_heat_source.hpp"

#include "vibrotherm/mesh/plex/point_origin.hpp"

namespace vibrotherm::coupling {

DampingHeatSource::~DampingHeatSource() {
  (void)MatDestroy(&D_);
  (void)VecDestroy(&energy_);
  (void)VecDestroy(&work_);
}

PetscErrorCode DampingHeatSource::Setup(wave::WaveSolver* waves, Mat transfer) {
  PetscFunctionBeginUser;
  bool kept;
  PetscCall(waves->KeepDampingEnergy(&kept));
  PetscCheck(kept, PetscObjectComm((PetscObject)transfer), PETSC_ERR_USER_INPUT,
             "-material_damping_heat: not with local time stepping (-wave_lts on), which accounts the damping per kick");
  waves_ = waves;
  PetscCall(PetscObjectReference((PetscObject)transfer));
  D_ = transfer;
  PetscCall(MatCreateVecs(D_, &energy_, &work_));
  PetscInt n;
  PetscCall(VecGetLocalSize(work_, &n));
  cumulative_.assign(n, 0.0);
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::StepEnergy(double t) {
  PetscFunctionBeginUser;
  PetscScalar* E;
  if (mode_ == ReplayMode::Off) {
    PetscCall(waves_->TakeDampingEnergy(energy_));
    PetscCall(MatMult(D_, energy_, work_));
    PetscCall(VecGetArray(work_, &E));
    for (std::size_t i = 0; i < cumulative_.size(); ++i) cumulative_[i] += PetscRealPart(E[i]);
  } else {  // what the replay has deposited by t, less what was already
    const std::vector<double> now = replay_.At(t, mode_);
    PetscCall(VecGetArray(work_, &E));
    for (std::size_t i = 0; i < cumulative_.size(); ++i) E[i] = now[i] - cumulative_[i];
    cumulative_ = now;
  }
  PetscCall(VecRestoreArray(work_, &E));
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::AddLoad(double t, double interval, Vec Q) {
  PetscFunctionBeginUser;
  PetscCall(StepEnergy(t));
  if (replay_.recording()) replay_.Sample(t, cumulative_);
  PetscCall(AddEnergyLoad(work_, interval, Q, &deposited_));
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::AddAverageLoad(Vec Q) {
  PetscFunctionBeginUser;
  const std::vector<double> rise = replay_.increase();
  PetscScalar* q;
  PetscCall(VecGetArray(Q, &q));
  for (std::size_t i = 0; i < rise.size(); ++i) q[i] += rise[i] / replay_.span();
  PetscCall(VecRestoreArray(Q, &q));
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::Finish(const std::string&) {
  PetscFunctionBeginUser;
  waves_ = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const {
  PetscFunctionBeginUser;
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(specimen.heat, specimen.heat_origin, &keys));
  SaveExchange(checkpoint, "damping_heat", keys, "cumulative", cumulative_);
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  // Checkpoints follow a heat step: nothing was taken since (the restored waves start counting afresh).
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(specimen.heat, specimen.heat_origin, &keys));
  PetscCall(RestoreExchange(checkpoint, "damping_heat", keys, "cumulative", &cumulative_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

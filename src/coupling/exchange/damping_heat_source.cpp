#include "vibrotherm/coupling/exchange/damping_heat_source.hpp"

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
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::AddLoad(double, double interval, Vec Q) {
  PetscFunctionBeginUser;
  PetscCall(waves_->TakeDampingEnergy(energy_));
  PetscCall(MatMult(D_, energy_, work_));
  PetscCall(AddEnergyLoad(work_, interval, Q, &deposited_));
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::Finish(const std::string&) {
  PetscFunctionBeginUser;
  waves_ = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::Save(store::Checkpoint& checkpoint, const mesh::Specimen&) const {
  PetscFunctionBeginUser;
  checkpoint.PutShared("damping_heat/deposited", {deposited_});
  PetscFunctionReturn(0);
}

PetscErrorCode DampingHeatSource::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen&) {
  PetscFunctionBeginUser;
  // Checkpoints follow a heat step: nothing was taken since (the restored waves start counting afresh).
  std::vector<double> deposited;
  PetscCall(checkpoint.GetShared("damping_heat/deposited", &deposited, 1));
  deposited_ = deposited[0];
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

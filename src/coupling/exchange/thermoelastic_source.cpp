#include "vibrotherm/coupling/exchange/thermoelastic_source.hpp"

namespace vibrotherm::coupling {

ThermoelasticSource::~ThermoelasticSource() {
  (void)MatDestroy(&B_);
  (void)VecDestroy(&u_prev_);
  (void)VecDestroy(&work_);
}

PetscErrorCode ThermoelasticSource::Setup(const wave::WaveSolver& waves, Mat transfer) {
  PetscFunctionBeginUser;
  waves_ = &waves;
  PetscCall(PetscObjectReference((PetscObject)transfer));
  B_ = transfer;
  Vec u, v;
  PetscCall(waves.GetFields(&u, &v));
  PetscCall(VecDuplicate(u, &u_prev_));
  PetscCall(VecCopy(u, u_prev_));
  PetscCall(waves.RestoreFields(&u, &v));
  PetscCall(MatCreateVecs(B_, nullptr, &work_));
  PetscFunctionReturn(0);
}

PetscErrorCode ThermoelasticSource::AddLoad(double, double interval, Vec Q) {
  PetscFunctionBeginUser;
  Vec u, v;
  PetscCall(waves_->GetFields(&u, &v));
  PetscCall(VecAYPX(u_prev_, -1.0, u));  // Δu = u − u_prev
  PetscCall(MatMult(B_, u_prev_, work_));
  PetscCall(VecCopy(u, u_prev_));
  PetscCall(waves_->RestoreFields(&u, &v));
  PetscCall(AddEnergyLoad(work_, interval, Q, &deposited_));
  PetscFunctionReturn(0);
}

PetscErrorCode ThermoelasticSource::Finish(const std::string&) {
  PetscFunctionBeginUser;
  waves_ = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode ThermoelasticSource::Save(store::Checkpoint& checkpoint, const mesh::Specimen&) const {
  PetscFunctionBeginUser;
  checkpoint.PutShared("thermoelastic/deposited", {deposited_});
  PetscFunctionReturn(0);
}

PetscErrorCode ThermoelasticSource::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen&) {
  PetscFunctionBeginUser;
  std::vector<double> deposited;
  PetscCall(checkpoint.GetShared("thermoelastic/deposited", &deposited, 1));
  deposited_ = deposited[0];
  // The last exchange took the displacement the wave solver holds now (checkpoints follow a heat step).
  Vec u, v;
  PetscCall(waves_->GetFields(&u, &v));
  PetscCall(VecCopy(u, u_prev_));
  PetscCall(waves_->RestoreFields(&u, &v));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

#include "vibrotherm/coupling/thermal_stress.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::coupling {

ThermalStress::~ThermalStress() {
  for (Mat* m : {&B_, &minus_S_}) (void)MatDestroy(m);
  for (Vec* v : {&c_inv_, &phi_, &phi_new_, &g_, &g_rate_}) (void)VecDestroy(v);
}

PetscErrorCode ThermalStress::Setup(wave::WaveSolver* waves, Mat transfer, Vec capacity_inverse, Vec theta,
                                    double T0) {
  PetscFunctionBeginUser;
  PetscLogEvent setup_event;
  PetscCall(PetscLogEventRegister("ThermalStressSet", MAT_CLASSID, &setup_event));
  PetscCall(PetscLogEventRegister("ThermalStress", MAT_CLASSID, &force_event_));
  PetscCall(PetscLogEventBegin(setup_event, 0, 0, 0, 0));
  waves_ = waves;
  T0_ = T0;
  t_n_ = waves->time();
  PetscCall(PetscObjectReference((PetscObject)transfer));
  B_ = transfer;
  PetscCall(PetscObjectReference((PetscObject)capacity_inverse));
  c_inv_ = capacity_inverse;
  // −S = −(1/T0) Bᵀ C⁻¹ B: wave × wave, symmetric negative semidefinite.
  Mat scaled;
  PetscCall(MatDuplicate(B_, MAT_COPY_VALUES, &scaled));
  PetscCall(MatDiagonalScale(scaled, c_inv_, nullptr));
  PetscCall(MatTransposeMatMult(B_, scaled, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &minus_S_));
  PetscCall(MatDestroy(&scaled));
  PetscCall(MatScale(minus_S_, -1.0 / T0_));
  PetscCall(VecDuplicate(c_inv_, &phi_));
  PetscCall(VecDuplicate(c_inv_, &phi_new_));
  PetscCall(MatCreateVecs(B_, &g_, nullptr));
  PetscCall(VecDuplicate(g_, &g_rate_));
  PetscCall(Phi(theta, phi_));
  PetscCall(MatMultTranspose(B_, phi_, g_));
  PetscCall(VecScale(g_, -1.0 / T0_));
  PetscCall(VecSet(g_rate_, 0.0));  // no history yet: φ held
  PetscCall(PetscLogEventEnd(setup_event, 0, 0, 0, 0));
  PetscCall(waves_->SetBodyForce(this));
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::Phi(Vec theta, Vec phi) const {
  PetscFunctionBeginUser;
  Vec u, v;
  PetscCall(waves_->GetFields(&u, &v));
  PetscCall(MatMult(B_, u, phi));
  PetscCall(waves_->RestoreFields(&u, &v));
  PetscCall(VecPointwiseMult(phi, phi, c_inv_));
  PetscCall(VecAYPX(phi, -1.0, theta));  // θ − C⁻¹B u
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::Update(Vec theta, double t) {
  PetscFunctionBeginUser;
  if (!waves_) PetscFunctionReturn(0);
  const double H = t - t_n_;
  if (H <= 0.0) PetscFunctionReturn(0);
  PetscCall(Phi(theta, phi_new_));
  PetscCall(VecAYPX(phi_, -1.0, phi_new_));  // φ_n+1 − φ_n
  PetscCall(MatMultTranspose(B_, phi_, g_rate_));
  PetscCall(VecScale(g_rate_, -1.0 / (T0_ * H)));
  PetscCall(VecCopy(phi_new_, phi_));
  PetscCall(MatMultTranspose(B_, phi_, g_));
  PetscCall(VecScale(g_, -1.0 / T0_));
  t_n_ = t;
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::Detach() {
  PetscFunctionBeginUser;
  if (waves_) PetscCall(waves_->SetBodyForce(nullptr));
  waves_ = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::Force(double t, Vec u, Vec f) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(force_event_, 0, 0, 0, 0));
  PetscCall(VecWAXPY(f, t - t_n_, g_rate_, g_));
  PetscCall(MatMultAdd(minus_S_, u, f, f));
  PetscCall(PetscLogEventEnd(force_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::MaxFrequencySquared(Vec mass, double* omega2) const {
  PetscFunctionBeginUser;
  // Gershgorin: every eigenvalue of M⁻¹S is at most the largest row sum of |S_ij| / m_i.
  PetscInt rstart, rend;
  PetscCall(MatGetOwnershipRange(minus_S_, &rstart, &rend));
  const PetscScalar* m;
  PetscCall(VecGetArrayRead(mass, &m));
  double local = 0.0;
  for (PetscInt row = rstart; row < rend; ++row) {
    PetscInt n;
    const PetscScalar* values;
    PetscCall(MatGetRow(minus_S_, row, &n, nullptr, &values));
    double sum = 0.0;
    for (PetscInt k = 0; k < n; ++k) sum += std::abs(PetscRealPart(values[k]));
    PetscCall(MatRestoreRow(minus_S_, row, &n, nullptr, &values));
    local = std::max(local, sum / PetscRealPart(m[row - rstart]));
  }
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscCallMPI(MPI_Allreduce(&local, omega2, 1, MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)minus_S_)));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

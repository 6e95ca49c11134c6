#include "vibrotherm/coupling/exchange/thermal_stress.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vibrotherm::coupling {

ThermalStress::~ThermalStress() {
  (void)MatDestroy(&B_);
  for (Vec* v : {&c_inv_, &weight_, &heat_work_, &phi_, &phi_new_, &g_, &g_rate_}) (void)VecDestroy(v);
}

PetscErrorCode ThermalStress::Setup(wave::WaveSolver* waves, Mat transfer, Vec capacity_inverse, Vec theta,
                                    double T0) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventRegister("ThermalStress", MAT_CLASSID, &force_event_));
  waves_ = waves;
  T0_ = T0;
  t_n_ = waves->time();
  PetscCall(PetscObjectReference((PetscObject)transfer));
  B_ = transfer;
  PetscCall(PetscObjectReference((PetscObject)capacity_inverse));
  c_inv_ = capacity_inverse;
  // S u = Bᵀ C⁻¹ B u / T0 is applied as three products, never assembled: BᵀC⁻¹B
  // couples wave dofs through every heat dof between them (8x the flops of B and Bᵀ
  // in the paper scene, measured).
  PetscCall(VecDuplicate(c_inv_, &weight_));
  PetscCall(VecCopy(c_inv_, weight_));
  PetscCall(VecScale(weight_, -1.0 / T0_));
  PetscCall(VecDuplicate(c_inv_, &heat_work_));
  PetscCall(VecDuplicate(c_inv_, &phi_));
  PetscCall(VecDuplicate(c_inv_, &phi_new_));
  PetscCall(MatCreateVecs(B_, &g_, nullptr));
  PetscCall(VecDuplicate(g_, &g_rate_));
  PetscCall(Phi(theta, phi_));
  PetscCall(MatMultTranspose(B_, phi_, g_));
  PetscCall(VecScale(g_, -1.0 / T0_));
  PetscCall(VecSet(g_rate_, 0.0));  // no history yet: φ held
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
  PetscCall(MatMult(B_, u, heat_work_));
  PetscCall(VecPointwiseMult(heat_work_, heat_work_, weight_));  // −C⁻¹B u / T0
  PetscCall(VecWAXPY(f, t - t_n_, g_rate_, g_));
  PetscCall(MatMultTransposeAdd(B_, heat_work_, f, f));  // g + (t − t_n) ġ − S u
  PetscCall(PetscLogEventEnd(force_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::MaxFrequencySquared(Vec mass, double* omega2) const {
  PetscFunctionBeginUser;
  // Gershgorin: every eigenvalue of M⁻¹S is at most the largest row sum of |S_ij| / m_i,
  // and Σ_j |S_ij| ≤ (|B|ᵀ C⁻¹ |B| 1)_i / T0 (S is not assembled).
  Mat abs_B;
  PetscCall(MatDuplicate(B_, MAT_DO_NOT_COPY_VALUES, &abs_B));
  PetscInt rstart, rend;
  PetscCall(MatGetOwnershipRange(B_, &rstart, &rend));
  std::vector<PetscScalar> values;
  for (PetscInt row = rstart; row < rend; ++row) {
    PetscInt n;
    const PetscInt* cols;
    const PetscScalar* v;
    PetscCall(MatGetRow(B_, row, &n, &cols, &v));
    values.resize(n);
    for (PetscInt k = 0; k < n; ++k) values[k] = std::abs(PetscRealPart(v[k]));
    PetscCall(MatSetValues(abs_B, 1, &row, n, cols, values.data(), INSERT_VALUES));
    PetscCall(MatRestoreRow(B_, row, &n, &cols, &v));
  }
  PetscCall(MatAssemblyBegin(abs_B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(abs_B, MAT_FINAL_ASSEMBLY));
  Vec ones, heat, sums;
  PetscCall(MatCreateVecs(abs_B, &ones, &heat));
  PetscCall(VecDuplicate(ones, &sums));
  PetscCall(VecSet(ones, 1.0));
  PetscCall(MatMult(abs_B, ones, heat));
  PetscCall(VecPointwiseMult(heat, heat, c_inv_));
  PetscCall(MatMultTranspose(abs_B, heat, sums));
  PetscCall(VecPointwiseDivide(sums, sums, mass));
  PetscReal largest;
  PetscCall(VecMax(sums, nullptr, &largest));
  *omega2 = largest / T0_;
  for (Vec* v : {&ones, &heat, &sums}) PetscCall(VecDestroy(v));
  PetscCall(MatDestroy(&abs_B));
  PetscFunctionReturn(0);
}

namespace {

PetscErrorCode PutVector(store::Checkpoint& checkpoint, const char* name, Vec v, DM dm, const mesh::PointOrigin& origin) {
  PetscFunctionBeginUser;
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(dm, origin, &keys));
  PetscCall(store::PutOwnedValues(checkpoint, name, keys, v));
  PetscFunctionReturn(0);
}

PetscErrorCode GetVector(const store::Checkpoint& checkpoint, const char* name, Vec v, DM dm,
                         const mesh::PointOrigin& origin) {
  PetscFunctionBeginUser;
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(dm, origin, &keys));
  PetscCall(store::GetOwnedValues(checkpoint, name, keys, v));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ThermalStress::Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const {
  PetscFunctionBeginUser;
  PetscCall(PutVector(checkpoint, "thermal_stress/phi", phi_, specimen.heat, specimen.heat_origin));
  PetscCall(PutVector(checkpoint, "thermal_stress/g", g_, specimen.wave, specimen.wave_origin));
  PetscCall(PutVector(checkpoint, "thermal_stress/g_rate", g_rate_, specimen.wave, specimen.wave_origin));
  checkpoint.PutShared("thermal_stress/t_n", {t_n_});
  PetscFunctionReturn(0);
}

PetscErrorCode ThermalStress::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  PetscCall(GetVector(checkpoint, "thermal_stress/phi", phi_, specimen.heat, specimen.heat_origin));
  PetscCall(GetVector(checkpoint, "thermal_stress/g", g_, specimen.wave, specimen.wave_origin));
  PetscCall(GetVector(checkpoint, "thermal_stress/g_rate", g_rate_, specimen.wave, specimen.wave_origin));
  std::vector<double> t_n;
  PetscCall(checkpoint.GetShared("thermal_stress/t_n", &t_n, 1));
  t_n_ = t_n[0];
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

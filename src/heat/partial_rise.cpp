// The partial rise θ_p (heat_solver.hpp EnablePartialRise): the share of θ one load causes.
// Every step of the theta family with a load constant over the step solves
//   M (θ_n − θ_{n−1}) / h + K (θ_{n−1} + w Δθ) = Q + G
// (w = 1 backward Euler, 1/2 Crank–Nicolson; K holds the convective film). The same step
// for θ_p with its load alone is (K + M/(w h)) Δθ_p = (Q_p − K θ_p,{n−1}) / w: the very
// operator J = K + shift M (shift = 1/(w h)) the TS has just solved with, so one more
// solve with the factors (or preconditioner) it already holds. Sink rows stay 0.
#include "vibrotherm/heat/heat_solver.hpp"

namespace vibrotherm::heat {

PetscErrorCode HeatSolver::EnablePartialRise() {
  PetscFunctionBeginUser;
  if (partial_) PetscFunctionReturn(0);
  for (Vec* v : {&partial_, &partial_load_, &partial_step_}) {
    PetscCall(VecDuplicate(theta_, v));
    PetscCall(VecSet(*v, 0.0));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::SetPartialLoad(Vec load) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(load, partial_load_));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AdvancePartial() {
  PetscFunctionBeginUser;
  bool family;
  double w;
  PetscCall(ThetaWeight(ts_, &family, &w));
  const char* prefix;
  PetscCall(TSGetOptionsPrefix(ts_, &prefix));
  PetscCheck(family, PetscObjectComm((PetscObject)dm_), PETSC_ERR_USER_INPUT,
             "-%sts_type: the defect's share of the heat (the camera's verdict with other heat sources) is stepped "
             "with the heat's own steps, which needs a theta-family integrator (beuler, cn, theta)",
             prefix ? prefix : "");
  Vec rhs = partial_step_;
  PetscCall(MatMult(K_, partial_, rhs));
  PetscCall(VecAYPX(rhs, -1.0, partial_load_));  // Q_p − K θ_p
  PetscCall(VecScale(rhs, 1.0 / w));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(rhs, &rstart, nullptr));
  PetscScalar* r;
  PetscCall(VecGetArray(rhs, &r));
  for (PetscInt row : boundary_.sink_rows) r[row - rstart] = 0.0;
  PetscCall(VecRestoreArray(rhs, &r));
  SNES snes;
  KSP ksp;
  PetscCall(TSGetSNES(ts_, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSolve(ksp, rhs, work_));  // J, factored or preconditioned for this very step
  PetscCall(VecAXPY(partial_, 1.0, work_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat

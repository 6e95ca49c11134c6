// How loads reach a probe through the coupled integrator: the adjoint of its
// steps (used by coupling/crack_near_field to take the heat mesh's response
// to the last few heat steps' friction heat out of the crack probes).
//
// A theta-family step of length dt (w = 1: backward Euler) is
//   (M/dt + wK) θ_n = (M/dt − (1−w)K) θ_{n−1} + Q_n   on the free rows, θ = 0 on sinks,
// i.e. θ_n = P (wJ)⁻¹ (B θ_{n−1} + Q_n) with J = K + M/(w dt) (the TS's Jacobian,
// sinks as identity rows with zeroed columns), B = M/dt − (1−w)K and P the
// projection on the free rows. A load Q in step n − k adds
//   φᵀ [P(wJ)⁻¹B]^k P(wJ)⁻¹ Q = w_kᵀ Q,  w_0 = P(wJ)⁻¹φ,  w_k = P(wJ)⁻¹ B w_{k−1}
// to φᵀθ_n (J, B symmetric): one solve per lag, with a factorisation of its own.
#include "vibrotherm/heat/heat_solver.hpp"

#include <petscdmplex.h>

#include <cmath>

namespace vibrotherm::heat {

PetscErrorCode HeatSolver::ProbeFunctional(std::size_t probe, Vec phi) const {
  PetscFunctionBeginUser;
  PetscSection section;
  PetscCall(DMGetLocalSection(dm_, &section));
  Vec local;
  PetscCall(DMGetLocalVector(dm_, &local));
  PetscCall(VecSet(local, 0.0));
  const fe::LocatedPoint& p = probes_.at(probe);
  if (p.cell >= 0) PetscCall(DMPlexVecSetClosure(dm_, section, local, p.cell, p.phi.data(), INSERT_VALUES));
  PetscCall(VecSet(phi, 0.0));
  PetscCall(DMLocalToGlobal(dm_, local, ADD_VALUES, phi));
  PetscCall(DMRestoreLocalVector(dm_, &local));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::SetupResponseSolver(double dt, double w) {
  PetscFunctionBeginUser;
  const double shift = 1.0 / (w * dt);
  if (response_ksp_ && std::abs(shift - response_shift_) <= 1e-10 * shift) PetscFunctionReturn(0);
  if (!response_J_) {
    PetscCall(MatDuplicate(K_, MAT_DO_NOT_COPY_VALUES, &response_J_));
    PetscCall(MatSetOption(response_J_, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
    PetscCall(KSPCreate(PetscObjectComm((PetscObject)dm_), &response_ksp_));
    PetscCall(KSPSetOptionsPrefix(response_ksp_, "heat_response_"));
    PetscCall(ConfigureLinearSolver(response_ksp_, global_dofs_ <= kDirectSolveDofs));
    PetscCall(KSPSetFromOptions(response_ksp_));
  }
  PetscCall(AssembleJacobian(this, shift, response_J_));
  PetscCall(KSPSetOperators(response_ksp_, response_J_, response_J_));
  response_shift_ = shift;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::StepResponses(Vec phi, double dt, PetscInt steps, std::vector<Vec>* w,
                                         bool* supported) {
  PetscFunctionBeginUser;
  w->clear();
  PetscBool theta_family;
  PetscCall(PetscObjectTypeCompareAny((PetscObject)coupled_ts_, &theta_family, TSTHETA, TSBEULER, TSCN, ""));
  *supported = theta_family;
  if (!theta_family) PetscFunctionReturn(0);
  PetscReal weight;
  PetscCall(TSThetaGetTheta(coupled_ts_, &weight));
  PetscCall(SetupResponseSolver(dt, weight));
  Vec rhs, mass;
  PetscCall(VecDuplicate(theta_, &rhs));
  PetscCall(VecDuplicate(theta_, &mass));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(rhs, &rstart, nullptr));
  for (PetscInt k = 0; k < steps; ++k) {
    if (k == 0) {
      PetscCall(VecCopy(phi, rhs));
    } else {  // B w_{k−1} = (M/dt − (1 − w) K) w_{k−1}
      PetscCall(MatMult(K_, w->back(), rhs));
      PetscCall(VecScale(rhs, -(1.0 - weight)));
      PetscCall(MatMult(M_, w->back(), mass));
      PetscCall(VecAXPY(rhs, 1.0 / dt, mass));
    }
    Vec next;
    PetscCall(VecDuplicate(theta_, &next));
    PetscCall(KSPSolve(response_ksp_, rhs, next));
    PetscCall(VecScale(next, 1.0 / weight));
    PetscScalar* x;
    PetscCall(VecGetArray(next, &x));
    for (PetscInt row : boundary_.sink_rows) x[row - rstart] = 0.0;  // P
    PetscCall(VecRestoreArray(next, &x));
    w->push_back(next);
  }
  PetscCall(VecDestroy(&rhs));
  PetscCall(VecDestroy(&mass));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat

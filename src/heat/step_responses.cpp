// How loads reach a probe through the coupled integrator: the adjoint of its
// steps (used by coupling/exchange/crack_near_field to take the heat mesh's response
// to the last few heat steps' friction heat out of the crack probes).
//
// A theta-family step of length h (w = 1: backward Euler) is
//   (M/h + wK) θ_n = (M/h − (1−w)K) θ_{n−1} + Q_n   on the free rows, θ = 0 on sinks,
// i.e. θ_n = P (wJ_n)⁻¹ (B_n θ_{n−1} + Q_n) with J_n = K + M/(w h_n) (the TS's
// Jacobian, sinks as identity rows with zeroed columns), B_n = M/h_n − (1−w)K and
// P the projection on the free rows. A load Q in step n − k adds w_kᵀQ to φᵀθ_n,
//   w_0 = P(wJ_n)⁻¹ φ,  w_k = P(wJ_{n−k})⁻¹ B_{n−k+1} w_{k−1}
// (J, B symmetric): one solve per lag, with factorisations of its own, kept for
// the last few step lengths.
#include "vibrotherm/heat/heat_solver.hpp"

#include <petscdmplex.h>

#include <cmath>

namespace vibrotherm::heat {

PetscErrorCode HeatSolver::ResponseSolver(double dt, double w, KSP* ksp) {
  PetscFunctionBeginUser;
  PetscCall(responses_.Get(1.0 / (w * dt), ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::StepResponses(Vec phi, const std::vector<double>& lengths, std::vector<Vec>* w,
                                         bool* supported) {
  PetscFunctionBeginUser;
  w->clear();
  double weight;
  PetscCall(ThetaWeight(coupled_ts_, supported, &weight));
  if (!*supported) PetscFunctionReturn(0);
  Vec rhs, mass;
  PetscCall(VecDuplicate(theta_, &rhs));
  PetscCall(VecDuplicate(theta_, &mass));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(rhs, &rstart, nullptr));
  for (std::size_t k = 0; k < lengths.size(); ++k) {
    if (k == 0) {
      PetscCall(VecCopy(phi, rhs));
    } else {  // B_{n−k+1} w_{k−1} = (M/h − (1 − w) K) w_{k−1}, h the step after
      PetscCall(MatMult(K_, w->back(), rhs));
      PetscCall(VecScale(rhs, -(1.0 - weight)));
      PetscCall(MatMult(M_, w->back(), mass));
      PetscCall(VecAXPY(rhs, 1.0 / lengths[k - 1], mass));
    }
    KSP ksp;
    PetscCall(ResponseSolver(lengths[k], weight, &ksp));
    Vec next;
    PetscCall(VecDuplicate(theta_, &next));
    PetscCall(KSPSolve(ksp, rhs, next));
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

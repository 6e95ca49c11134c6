// The wave solver's body force (body_force.hpp): attached once before the first
// step, added to every acceleration, its work accounted per step.
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {

PetscErrorCode WaveSolver::SetBodyForce(BodyForce* force) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  body_ = force;
  if (!force) PetscFunctionReturn(0);
  PetscCheck(!second_order_, comm, PETSC_ERR_SUP,
             "%s with -wave_ts_type alpha2 is not supported yet: use an explicit type", force->name());
  PetscCheck(!lts_active_, comm, PETSC_ERR_SUP,
             "%s with local time stepping is not supported yet: add -wave_lts off", force->name());
  // The step is fixed before the first step: velocity Verlet's conserved energy depends on it.
  PetscCheck(steps_ == 0, comm, PETSC_ERR_ORDER, "%s: a body force is attached before the first wave step",
             force->name());
  if (!body_f_)
    for (Vec* v : {&body_f_, &body_u_, &body_a_, &body_f_end_}) PetscCall(VecDuplicate(op_.mass(), v));
  PetscCall(VecSet(body_f_, 0.0));
  PetscCall(VecCopy(u_, body_u_));
  PetscCall(force->Force(time_, u_, body_f_end_));
  double omega2;
  PetscCall(force->MaxFrequencySquared(op_.mass(), &omega2));
  PetscCall(step_.IncludeBulkStiffness(omega2, force->name()));
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::AddBodyForce(double t, Vec u, Vec a) {
  PetscFunctionBeginUser;
  PetscCall(body_->Force(t, u, body_f_));
  PetscCall(VecPointwiseMult(body_a_, body_f_, op_.inverse_mass()));
  PetscCall(VecAXPY(a, 1.0, body_a_));
  PetscFunctionReturn(0);
}

/// Σ f_i (u_i − before_i) over this rank's dofs (f: weight × a + (1 − weight) × b).
static PetscErrorCode LocalWork(Vec a, Vec b, double weight, Vec u, Vec before, double* work) {
  PetscFunctionBeginUser;
  const PetscScalar *fa, *fb, *now, *was;
  PetscInt n;
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(VecGetArrayRead(a, &fa));
  PetscCall(VecGetArrayRead(b, &fb));
  PetscCall(VecGetArrayRead(u, &now));
  PetscCall(VecGetArrayRead(before, &was));
  *work = 0.0;
  for (PetscInt i = 0; i < n; ++i) *work += PetscRealPart((weight * fa[i] + (1.0 - weight) * fb[i]) * (now[i] - was[i]));
  PetscCall(VecRestoreArrayRead(before, &was));
  PetscCall(VecRestoreArrayRead(u, &now));
  PetscCall(VecRestoreArrayRead(b, &fb));
  PetscCall(VecRestoreArrayRead(a, &fa));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::AccountBodyWork(double t, Vec u) {
  PetscFunctionBeginUser;
  // Velocity Verlet: the kick's force (the last evaluated, at the midpoint) times the
  // step's displacement is the work the kick did, to rounding. Other types: the
  // trapezoidal rule between the forces at the step's ends (to their order).
  double work;
  if (velocity_verlet_) {
    PetscCall(LocalWork(body_f_, body_f_, 1.0, u, body_u_, &work));
  } else {
    PetscCall(body_->Force(t, u, body_a_));
    PetscCall(LocalWork(body_a_, body_f_end_, 0.5, u, body_u_, &work));
    PetscCall(VecCopy(body_a_, body_f_end_));
  }
  body_work_ += work;  // local sums only: Energy() reduces
  PetscCall(VecCopy(u, body_u_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

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
  // The step is fixed before the first step: velocity Verlet's conserved energy depends on it.
  PetscCheck(steps_ == 0, comm, PETSC_ERR_ORDER, "%s: a body force is attached before the first wave step",
             force->name());
  if (!body_f_)
    for (Vec* v : {&body_f_, &body_u_, &body_a_}) PetscCall(VecDuplicate(M_, v));
  PetscCall(VecSet(body_f_, 0.0));
  PetscCall(VecCopy(u_, body_u_));
  double omega2;
  PetscCall(force->MaxFrequencySquared(M_, &omega2));
  PetscCall(step_.IncludeBulkStiffness(omega2, force->name()));
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::AddBodyForce(double t, Vec u, Vec a) {
  PetscFunctionBeginUser;
  PetscCall(body_->Force(t, u, body_f_));
  PetscCall(VecPointwiseMult(body_a_, body_f_, Minv_));
  PetscCall(VecAXPY(a, 1.0, body_a_));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::AccountBodyWork(Vec u) {
  PetscFunctionBeginUser;
  // The last force evaluated (velocity Verlet: the kick's, at the midpoint) times
  // the step's displacement: the work the kick did, to rounding. Local sums only.
  const PetscScalar *f, *now, *before;
  PetscInt n;
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(VecGetArrayRead(body_f_, &f));
  PetscCall(VecGetArrayRead(u, &now));
  PetscCall(VecGetArrayRead(body_u_, &before));
  double work = 0.0;
  for (PetscInt i = 0; i < n; ++i) work += PetscRealPart(f[i] * (now[i] - before[i]));
  PetscCall(VecRestoreArrayRead(body_u_, &before));
  PetscCall(VecRestoreArrayRead(u, &now));
  PetscCall(VecRestoreArrayRead(body_f_, &f));
  body_work_ += work;
  PetscCall(VecCopy(u, body_u_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

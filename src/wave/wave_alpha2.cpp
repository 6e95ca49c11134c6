// The implicit second-order path of the wave solver (-wave_ts_type alpha2):
// M A + C V + K U = f(t), prescribed components imposed on the acceleration.
#include <cmath>

#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {

PetscErrorCode WaveSolver::SetupAlpha2(MPI_Comm comm) {
  PetscFunctionBeginUser;
  // The TS works on views of the state, so every other part sees its solution.
  PetscCall(VecGetSubVector(X_, is_u_, &u_view_));
  PetscCall(VecGetSubVector(X_, is_v_, &v_view_));
  PetscCall(TS2SetSolution(ts_, u_view_, v_view_));
  PetscCall(DMCreateMatrix(dm_, &J_));
  PetscCall(TSSetI2Function(ts_, nullptr, I2Function, this));
  PetscCall(TSSetI2Jacobian(ts_, J_, J_, I2Jacobian, this));
  for (const Constraint& c : boundary_.constraints)
    PetscCheck(std::abs(c.d[0] * c.d[1]) < 1e-12 && std::abs(c.d[0] * c.d[2]) < 1e-12 &&
                   std::abs(c.d[1] * c.d[2]) < 1e-12,
               comm, PETSC_ERR_SUP,
               "-wave_ts_type alpha2 supports prescribed components along a coordinate axis only (inclined source or "
               "roller face found)");
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Forces(double t, Vec u, Vec v, Vec f) const {
  PetscFunctionBeginUser;
  PetscCall(op_.Apply(u, f));
  PetscCall(VecPointwiseMult(f, f, op_.mass()));  // −K u
  ForceState state;
  state.signal = SignalValues::At(excitation_.signal, t);
  PetscScalar* F;
  PetscCall(VecGetArray(f, &F));
  PetscCall(VecGetArrayRead(v, &state.velocity));
  PetscCall(VecGetArrayRead(op_.mass(), &state.mass));
  for (const auto& term : terms_) term->AddForce(state, F);
  PetscCall(VecRestoreArrayRead(op_.mass(), &state.mass));
  PetscCall(VecRestoreArrayRead(v, &state.velocity));
  PetscCall(VecRestoreArray(f, &F));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::I2Function(TS, PetscReal t, Vec U, Vec V, Vec A, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  PetscCall(self->Forces(t, U, V, F));  // F = f(U, V, t)
  PetscCall(VecScale(F, -1.0));
  PetscCall(VecPointwiseMult(self->force_, self->op_.mass(), A));
  PetscCall(VecAXPY(F, 1.0, self->force_));  // M A − f
  ForceState state;
  state.signal = SignalValues::At(self->excitation_.signal, t);
  PetscScalar* R;
  const PetscScalar* Acc;
  PetscCall(VecGetArray(F, &R));
  PetscCall(VecGetArrayRead(A, &Acc));
  PetscCall(VecGetArrayRead(self->op_.mass(), &state.mass));
  for (const auto& term : self->terms_) term->ConstrainResidual(state, Acc, R);
  PetscCall(VecRestoreArrayRead(self->op_.mass(), &state.mass));
  PetscCall(VecRestoreArrayRead(A, &Acc));
  PetscCall(VecRestoreArray(F, &R));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::I2Jacobian(TS, PetscReal, Vec, Vec, Vec, PetscReal shiftV, PetscReal shiftA, Mat J, Mat,
                                      void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  PetscCall(MatCopy(self->op_.stiffness(), J, SAME_NONZERO_PATTERN));
  PetscCall(VecCopy(self->op_.mass(), self->force_));
  PetscCall(VecScale(self->force_, shiftA));
  PetscCall(MatDiagonalSet(J, self->force_, ADD_VALUES));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(self->op_.mass(), &rstart, nullptr));
  for (const auto& term : self->terms_) PetscCall(term->AddJacobian(shiftV, rstart, J));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  const PetscScalar* mass;
  PetscCall(VecGetArrayRead(self->op_.mass(), &mass));
  for (const auto& term : self->terms_) PetscCall(term->ConstrainJacobian(shiftA, rstart, mass, J));
  PetscCall(VecRestoreArrayRead(self->op_.mass(), &mass));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

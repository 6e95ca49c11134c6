// The wave solver's energy accounting: per step, what the boundary terms
// exchange (radiated by dashpots, worked by the source); on request, the
// kinetic and strain energy and velocity Verlet's integrator term; the work
// of a body force (wave_body_force.cpp).
#include <algorithm>

#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {

PetscErrorCode WaveSolver::AccountStep(double t, double h) {
  PetscFunctionBeginUser;
  // Boundary quantities only: no full-vector copies, no reduction per step
  // (Energy() sums the ranks' accounts).
  Vec u = nullptr, v = nullptr;
  PetscCall(GetFields(&u, &v));
  if (body_) PetscCall(AccountBodyWork(t, u));  // before any end-state evaluation replaces the kick's force
  const bool end_state_forces =
      !reaction_from_kick_ && std::any_of(terms_.begin(), terms_.end(),
                                          [](const auto& term) { return term->needs_end_state_forces(); });
  if (end_state_forces && lts_active_) {  // the level forces of the end state, no new product
    PetscCall(lts_.InteriorAcceleration(force_));
    PetscCall(ApplyTerms(t, v, force_, 0.0));
  } else if (end_state_forces) {
    PetscCall(Acceleration(t, u, v, force_, 0.0));  // the supports' forces at the end state
  }
  StepState state;
  state.start = SignalValues::At(excitation_.signal, t - h);
  state.middle = SignalValues::At(excitation_.signal, t - 0.5 * h);
  state.end = SignalValues::At(excitation_.signal, t);
  state.h = h;
  state.reactions_from_kick = reaction_from_kick_;
  PetscCall(VecGetArrayRead(u, &state.u));
  PetscCall(VecGetArrayRead(v, &state.v));
  for (auto& term : terms_) term->Account(state, &accounted_);
  PetscCall(VecRestoreArrayRead(u, &state.u));
  PetscCall(VecRestoreArrayRead(v, &state.v));
  PetscCall(RestoreFields(&u, &v));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::IntegratorTerm(double dt, double* term) const {
  PetscFunctionBeginUser;
  *term = 0.0;
  if (!velocity_verlet_) PetscFunctionReturn(0);
  if (lts_active_) {
    Vec u, v;
    PetscCall(GetFields(&u, &v));
    PetscCall(lts_.IntegratorTerm(u, term));
    PetscCall(RestoreFields(&u, &v));
    PetscFunctionReturn(0);
  }
  // With A = −M⁻¹K: vᵀKv = −(M∘v)·(A v).
  Vec u, v, Av, Mv;
  PetscCall(GetFields(&u, &v));
  PetscCall(VecDuplicate(v, &Av));
  PetscCall(VecDuplicate(v, &Mv));
  PetscCall(VecPointwiseMult(Mv, v, op_.mass()));
  PetscCall(op_.Apply(v, Av));
  PetscScalar vKv;
  PetscCall(VecDot(Mv, Av, &vKv));
  PetscCall(VecDestroy(&Av));
  PetscCall(VecDestroy(&Mv));
  PetscCall(RestoreFields(&u, &v));
  *term = dt * dt / 8.0 * PetscRealPart(vKv);  // −(dt²/8) vᵀKv
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Energy(WaveEnergy* e) const {
  PetscFunctionBeginUser;
  Vec u, v, Au, Mu;
  PetscCall(GetFields(&u, &v));
  PetscCall(VecDuplicate(u, &Au));
  PetscCall(VecDuplicate(u, &Mu));
  PetscCall(VecPointwiseMult(Mu, v, op_.mass()));
  PetscScalar kinetic, strain;
  PetscCall(VecDot(Mu, v, &kinetic));
  PetscCall(VecPointwiseMult(Mu, u, op_.mass()));
  PetscCall(op_.Apply(u, Au));
  PetscCall(VecDot(Mu, Au, &strain));  // −uᵀKu
  PetscCall(VecDestroy(&Au));
  PetscCall(VecDestroy(&Mu));
  PetscCall(RestoreFields(&u, &v));
  const double lts_damped = lts_active_ ? lts_.damped() : 0.0;
  double local[4] = {accounted_.radiated, accounted_.work_source, body_work_, accounted_.damped + lts_damped}, global[4];
  PetscCallMPI(MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  e->radiated = global[0];
  e->work_source = global[1];
  e->work_body = global[2];
  e->damped = global[3];
  e->kinetic = 0.5 * PetscRealPart(kinetic);
  e->strain = -0.5 * PetscRealPart(strain);
  PetscCall(IntegratorTerm(step_.dt(), &e->integrator));
  e->integrator += integrator_offset_;
  if (interface_) PetscCall(interface_->Energies(&e->interface_stored, &e->dissipated));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

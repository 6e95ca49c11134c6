// The wave solver in checkpoints: u and v per owned dof (keyed by the dof's
// origin, so any partition can read them), time, step counts, the step
// control, the integrator-term offset and each rank's boundary accounts; and the
// warm start from a saved state (u and v only, scaled).
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {

PetscErrorCode WaveSolver::Save(store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) const {
  PetscFunctionBeginUser;
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(dm_, origin, &keys));
  const PetscScalar* x;
  PetscCall(VecGetArrayRead(X_, &x));
  const std::size_t n = keys.size();
  checkpoint.PutKeyed("wave/u", keys, 1, std::vector<double>(x, x + n));
  checkpoint.PutKeyed("wave/v", keys, 1, std::vector<double>(x + n, x + 2 * n));
  PetscCall(VecRestoreArrayRead(X_, &x));
  PetscInt ts_steps;
  PetscCall(TSGetStepNumber(ts_, &ts_steps));
  // The body force's end-of-step value (types other than Verlet): it was taken before the heat step changed the force.
  if (body_) PetscCall(store::PutOwnedValues(checkpoint, "wave/body_force_end", keys, body_f_end_));
  checkpoint.PutShared("wave/clock", {time_, static_cast<double>(steps_), static_cast<double>(ts_steps),
                                      integrator_offset_});
  checkpoint.PutShared("wave/step_control", step_.state());
  if (lts_active_)
    checkpoint.PutShared("wave/lts", {static_cast<double>(lts_.contact_level()),
                                      static_cast<double>(lts_.contact_refinements()), lts_.macro_step(),
                                      static_cast<double>(lts_.halvings())});
  std::vector<double> accounts = {accounted_.radiated, accounted_.work_source, body_work_, accounted_.damped,
                                  lts_active_ ? lts_.damped() : 0.0};
  for (const auto& term : terms_)
    for (double value : term->SavedAccount()) accounts.push_back(value);
  checkpoint.PutPerRank("wave/accounts", accounts);
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::LoadFields(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin,
                                      double scale, std::vector<long long>* owned_keys) {
  PetscFunctionBeginUser;
  std::vector<long long> local_keys;
  std::vector<long long>& keys = owned_keys ? *owned_keys : local_keys;
  PetscCall(mesh::OwnedDofKeys(dm_, origin, &keys));
  std::vector<double> u, v;
  PetscCall(checkpoint.GetKeyed("wave/u", keys, 1, &u));
  PetscCall(checkpoint.GetKeyed("wave/v", keys, 1, &v));
  PetscScalar* x;
  PetscCall(VecGetArray(X_, &x));
  for (std::size_t i = 0; i < keys.size(); ++i) {  // scale 1: the values bit for bit
    x[i] = scale * u[i];
    x[keys.size() + i] = scale * v[i];
  }
  PetscCall(VecRestoreArray(X_, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Restore(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscCheck(!second_order_, comm, PETSC_ERR_SUP, "-restart: the implicit wave TS (alpha2) is not checkpointed");
  std::vector<long long> keys;  // the owned dofs' keys, for the body force's values below
  PetscCall(LoadFields(checkpoint, origin, 1.0, &keys));
  std::vector<double> clock, control, accounts;
  PetscCall(checkpoint.GetShared("wave/clock", &clock, 4));
  PetscCall(checkpoint.GetShared("wave/step_control", &control, 3));
  PetscCall(checkpoint.GetPerRank("wave/accounts", &accounts));
  time_ = clock[0];
  steps_ = static_cast<PetscInt>(clock[1]);
  integrator_offset_ = clock[3];
  step_.set_state(control);
  if (lts_active_) {  // the contact's level; the level forces are recomputed from the state
    std::vector<double> lts;
    PetscCall(checkpoint.GetShared("wave/lts", &lts, 4));
    PetscCall(lts_.set_contact_state(static_cast<PetscInt>(lts[0]), static_cast<PetscInt>(lts[1]), lts[2],
                                     static_cast<PetscInt>(lts[3])));
    lts_started_ = false;
  }
  PetscCall(TSSetTime(ts_, time_));
  PetscCall(TSSetStepNumber(ts_, static_cast<PetscInt>(clock[2])));
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  accounted_.radiated = accounts.at(0);
  accounted_.work_source = accounts.at(1);
  body_work_ = accounts.at(2);
  accounted_.damped = accounts.at(3);
  if (lts_active_) lts_.set_damped(accounts.at(4));
  std::size_t at = 5;
  for (auto& term : terms_) {
    const std::size_t n = term->SavedAccount().size();
    term->RestoreAccount(std::vector<double>(accounts.begin() + at, accounts.begin() + at + n));
    at += n;
  }
  if (body_) {  // what the solver remembers of the body force's last step
    PetscCall(store::GetOwnedValues(checkpoint, "wave/body_force_end", keys, body_f_end_));
    PetscCall(VecCopy(u_, body_u_));
  }
  // What the terms remember of the last step's end state is the state itself.
  Vec uv = nullptr, vv = nullptr;
  PetscCall(GetFields(&uv, &vv));
  StepState state;
  PetscCall(VecGetArrayRead(uv, &state.u));
  PetscCall(VecGetArrayRead(vv, &state.v));
  for (auto& term : terms_) term->Resume(state);
  PetscCall(VecRestoreArrayRead(uv, &state.u));
  PetscCall(VecRestoreArrayRead(vv, &state.v));
  PetscCall(RestoreFields(&uv, &vv));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::StartFromState(const store::Checkpoint& state, const mesh::PointOrigin& origin,
                                          double scale) {
  PetscFunctionBeginUser;
  PetscCall(LoadFields(state, origin, scale));
  double stored = 0.0, dissipated;
  if (interface_) {
    Vec uv, vv;
    PetscCall(GetFields(&uv, &vv));
    PetscCall(interface_->StartIn(uv));
    PetscCall(RestoreFields(&uv, &vv));
    PetscCall(interface_->Energies(&stored, &dissipated));
  }
  PetscCall(BookInitialEnergy(stored));  // the terms resume from this state there too
  PetscFunctionReturn(0);
}

std::vector<double> WaveSolver::Accumulated() const {
  return {time_, accounted_.radiated, accounted_.work_source, body_work_, accounted_.damped,
          lts_active_ ? lts_.damped() : 0.0};
}

PetscErrorCode WaveSolver::JumpAhead(const std::vector<double>& increments) {
  PetscFunctionBeginUser;
  PetscCheck(increments.size() == 6, PetscObjectComm((PetscObject)dm_), PETSC_ERR_ARG_SIZ, "6 increments expected");
  time_ += increments[0];
  accounted_.radiated += increments[1];
  accounted_.work_source += increments[2];
  body_work_ += increments[3];
  accounted_.damped += increments[4];
  if (lts_active_) lts_.set_damped(lts_.damped() + increments[5]);
  PetscCall(TSSetTime(ts_, time_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

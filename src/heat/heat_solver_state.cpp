// The heat solver in checkpoints (taken while the waves run: the coupled TS,
// fixed steps): θ per owned dof keyed by its origin, time, steps, the accounts,
// and the shift its Jacobian was factored with, so that a restart solves with
// the very same factors; the rungs' kept shifts, for the same reason (rung_solvers.hpp).
// The partial rise (EnablePartialRise) is kept the same way.
#include "vibrotherm/heat/heat_solver.hpp"

namespace vibrotherm::heat {

PetscErrorCode HeatSolver::Save(store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) const {
  PetscFunctionBeginUser;
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(dm_, origin, &keys));
  const PetscScalar* theta;
  PetscCall(VecGetArrayRead(theta_, &theta));
  checkpoint.PutKeyed("heat/theta", keys, 1, std::vector<double>(theta, theta + keys.size()));
  PetscCall(VecRestoreArrayRead(theta_, &theta));
  if (partial_) {
    const PetscScalar* p;
    PetscCall(VecGetArrayRead(partial_, &p));
    checkpoint.PutKeyed("heat/partial", keys, 1, std::vector<double>(p, p + keys.size()));
    PetscCall(VecRestoreArrayRead(partial_, &p));
  }
  PetscInt ts_steps;
  PetscReal dt;
  Mat J;
  PetscCall(TSGetStepNumber(ts_, &ts_steps));
  PetscCall(TSGetTimeStep(ts_, &dt));
  PetscCall(TSGetIJacobian(ts_, &J, nullptr, nullptr, nullptr));
  const auto shift = last_shift_.find(J);
  // The step taken (the free phase's ladder starts from it), not the TS's proposal for the next one.
  if (last_step_ > 0.0) dt = last_step_;
  PetscCall(SaveRungs(checkpoint));
  checkpoint.PutShared("heat/clock", {time_, static_cast<double>(steps_), static_cast<double>(ts_steps), dt,
                                      deposited_, boundary_loss_, peak_rise_,
                                      shift == last_shift_.end() ? 0.0 : shift->second});
  // Free: a periodic continuation's steps; the coupled TS's Jacobian shift too (it steps again afterwards).
  Mat coupled;
  PetscCall(TSGetIJacobian(coupled_ts_, &coupled, nullptr, nullptr, nullptr));
  const auto coupled_shift = last_shift_.find(coupled);
  checkpoint.PutShared("heat/integrator", {free_integrator() ? 1.0 : 0.0,
                                           coupled_shift == last_shift_.end() ? 0.0 : coupled_shift->second});
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::Restore(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) {
  PetscFunctionBeginUser;
  std::vector<long long> keys;
  PetscCall(mesh::OwnedDofKeys(dm_, origin, &keys));
  std::vector<double> theta, clock;
  PetscCall(RestoreRungs(checkpoint));
  PetscCall(checkpoint.GetKeyed("heat/theta", keys, 1, &theta));
  PetscCall(checkpoint.GetShared("heat/clock", &clock, 8));
  std::vector<double> integrator;
  PetscCall(checkpoint.GetShared("heat/integrator", &integrator, 2));
  if (integrator[0] == 1.0) {
    last_step_ = clock[3];
    PetscCall(UseFreeIntegrator());
    if (integrator[1] != 0.0) {  // the coupled TS resumes with the Jacobian it held
      Mat coupled;
      PetscCall(TSGetIJacobian(coupled_ts_, &coupled, nullptr, nullptr, nullptr));
      PetscCall(AssembleJacobian(this, integrator[1], coupled));
    }
  } else {
    PetscCall(UseCoupledIntegrator());
  }
  PetscScalar* x;
  PetscCall(VecGetArray(theta_, &x));
  std::copy(theta.begin(), theta.end(), x);
  PetscCall(VecRestoreArray(theta_, &x));
  PetscCall(VecCopy(theta_, theta_prev_));
  if (partial_ && checkpoint.Has("heat/partial")) {
    std::vector<double> partial;
    PetscCall(checkpoint.GetKeyed("heat/partial", keys, 1, &partial));
    PetscCall(VecGetArray(partial_, &x));
    std::copy(partial.begin(), partial.end(), x);
    PetscCall(VecRestoreArray(partial_, &x));
  }
  time_ = clock[0];
  steps_ = static_cast<PetscInt>(clock[1]);
  deposited_ = clock[4];
  boundary_loss_ = clock[5];
  peak_rise_ = clock[6];
  last_step_ = clock[3];
  PetscCall(TSSetTime(ts_, time_));
  PetscCall(TSSetStepNumber(ts_, static_cast<PetscInt>(clock[2])));
  PetscCall(TSSetTimeStep(ts_, clock[3]));
  if (clock[7] != 0.0) {  // the uninterrupted run keeps the Jacobian of its first step
    Mat J;
    PetscCall(TSGetIJacobian(ts_, &J, nullptr, nullptr, nullptr));
    PetscCall(AssembleJacobian(this, clock[7], J));
  }
  PetscFunctionReturn(0);
}

/// A rung solver's checkpoint name: by its TS's prefix (heat_, heat_free_), or the responses'.
std::string HeatSolver::RungsName(TS ts) {
  const char* prefix = nullptr;
  if (ts) (void)TSGetOptionsPrefix(ts, &prefix);
  return std::string("heat/rungs_") + (ts ? (prefix ? prefix : "") : "responses");
}

PetscErrorCode HeatSolver::SaveRungs(store::Checkpoint& checkpoint) const {
  PetscFunctionBeginUser;
  for (const auto& [ts, rungs] : rungs_) checkpoint.PutShared(RungsName(ts), rungs->KeptShifts());
  checkpoint.PutShared(RungsName(nullptr), responses_.KeptShifts());
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::RestoreRungs(const store::Checkpoint& checkpoint) {
  PetscFunctionBeginUser;
  std::vector<double> shifts;
  for (auto& [ts, rungs] : rungs_) {
    PetscCall(checkpoint.GetShared(RungsName(ts), &shifts));
    PetscCall(rungs->Remember(shifts));
  }
  PetscCall(checkpoint.GetShared(RungsName(nullptr), &shifts));
  PetscCall(responses_.Remember(shifts));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat

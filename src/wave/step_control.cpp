#include "vibrotherm/wave/step_control.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::wave {

double StepControl::RoundDown(double raw) {
  const double scale = std::pow(10.0, std::floor(std::log10(raw)) - 3);
  return std::floor(raw / scale) * scale;
}

double StepControl::Quantized(double raw, double q) {
  const double rounded = RoundDown(raw);
  if (!(q > 0.0)) return rounded;
  return q / std::ceil(q / rounded * (1.0 - 1e-12));
}

double StepControl::Limit(double omega2) const {
  return omega_dt_max_ / std::sqrt(omega_max_ * omega_max_ + omega2);
}

PetscErrorCode StepControl::Setup(MPI_Comm comm, double omega_max, double omega_dt_max, double cfl, double fixed_dt,
                                  const char* ts_type, double quantum) {
  PetscFunctionBeginUser;
  comm_ = comm;
  quantum_ = quantum;
  omega_max_ = omega_max;
  omega_dt_max_ = omega_dt_max;
  cfl_ = cfl;
  fixed_dt_ = fixed_dt;
  stable_dt_ = implicit() ? INFINITY : Limit(0.0);
  if (fixed_dt > 0.0) {
    PetscCheck(implicit() || fixed_dt <= stable_dt_, comm, PETSC_ERR_USER_INPUT,
               "-wave_dt %g s exceeds the stability limit %g s of -wave_ts_type %s (omega_max %g rad/s); use "
               "-wave_dt <= %g or -wave_cfl",
               fixed_dt, stable_dt_, ts_type, omega_max, stable_dt_);
    dt_ = fixed_dt;
  } else {
    // Implicit types: cfl of the explicit limit 2/ω_max, to resolve the fastest waves.
    dt_ = Quantized(cfl * (implicit() ? 2.0 / omega_max : stable_dt_), quantum_);
  }
  PetscFunctionReturn(0);
}

void StepControl::IncludeContact(double omega2) {
  contact_omega2_ = omega2;
  if (implicit() || fixed_dt_ > 0.0) return;
  dt_ = std::min(dt_, Quantized(cfl_ * Limit(omega2), quantum_));
}

PetscErrorCode StepControl::IncludeBulkStiffness(double omega2, const char* what) {
  PetscFunctionBeginUser;
  omega_max_ = std::sqrt(omega_max_ * omega_max_ + omega2);
  if (implicit()) PetscFunctionReturn(0);
  stable_dt_ = Limit(contact_omega2_);
  PetscCheck(fixed_dt_ <= 0.0 || fixed_dt_ <= stable_dt_, comm_, PETSC_ERR_USER_INPUT,
             "-wave_dt %g s exceeds the stability limit %g s with %s; use -wave_dt <= %g or -wave_cfl", fixed_dt_,
             stable_dt_, what, stable_dt_);
  if (fixed_dt_ <= 0.0) dt_ = std::min(dt_, Quantized(cfl_ * stable_dt_, quantum_));
  PetscFunctionReturn(0);
}

PetscErrorCode StepControl::Check(double omega2, double time, PetscInt steps, bool at_quantum, bool* changed) {
  PetscFunctionBeginUser;
  *changed = false;
  if (implicit()) PetscFunctionReturn(0);
  const double limit = Limit(omega2);
  stable_dt_ = limit;
  if (dt_ <= cfl_ * limit * (1.0 + 1e-12)) PetscFunctionReturn(0);
  if (quantum_ > 0.0 && !at_quantum && dt_ < limit) PetscFunctionReturn(0);  // still stable: shrink at the boundary
  // Shrink by at least 10 %, with twice the current contact stiffness as
  // headroom: velocity Verlet wants a step that changes rarely (a creeping step
  // was measured to destabilise it), and a contact that just started to bite
  // would otherwise shave off the last digit, step after step.
  const double reduced = Quantized(std::min(0.9 * dt_, cfl_ * Limit(2.0 * omega2)), quantum_);
  if (reductions_ == 0 && steps > 0)
    PetscCall(PetscPrintf(comm_,
                          "wave: the crack contact stiffened at t = %g s: time step reduced from %g to %g s "
                          "(further reductions are counted in summary.json)\n",
                          time, dt_, reduced));
  if (steps > 0) ++reductions_;
  dt_ = reduced;
  *changed = true;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

// energy.csv (J per metre of depth), rank 0, written atomically:
//   t,work_source,kinetic,strain,radiated,interface_stored,dissipated,
//   heat_deposited,heat_content,heat_boundary_loss,budget_error,integrator_correction,
//   heat_friction,heat_thermoelastic,work_thermal,damped,heat_damping   (heat_deposited split by its sources)
// budget_error = (work_source + work_thermal − kinetic − strain − integrator_correction −
//                 radiated − interface_stored − dissipated − damped) / max(work_source so far)
// work_thermal: the work of the thermal stress −βθI on the waves (-thermoelastic
// two_way, else 0): negative when the waves lose mechanical energy to the heat
// (thermoelastic damping); it also holds the reversible adiabatic exchange, which
// oscillates with the waves.
// (summary.json max_budget_error: the largest imbalance over the run's largest work);
// integrator_correction: the time integrator's own energy term (velocity
// Verlet: −(dt²/8) vᵀKv), without which the discrete energy is conserved only
// to O((ω dt)²).
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/store/atomic_file.hpp"

namespace vibrotherm::io {

struct EnergyRow {
  double t = 0, work_source = 0, kinetic = 0, strain = 0, radiated = 0, interface_stored = 0, dissipated = 0,
         heat_deposited = 0, heat_content = 0, heat_boundary_loss = 0, integrator_correction = 0;
  double heat_friction = 0, heat_thermoelastic = 0, work_thermal = 0;
  double damped = 0;  ///< dissipated by material damping (-material_loss_factor)
  double heat_damping = 0;  ///< heat deposited by it (-material_damping_heat)
};

class EnergyLog {
 public:
  /// resume_bytes >= 0: continue the interrupted run's file (checkpoint restart).
  PetscErrorCode Open(MPI_Comm comm, const std::string& path, long long resume_bytes = -1);
  /// Appends a row and returns its budget error.
  PetscErrorCode Record(const EnergyRow& row, double* budget_error);
  PetscErrorCode Finish();
  /// The largest imbalance of any row over the largest source work of the run:
  /// unlike the rows' running normalisation (huge relative errors of tiny
  /// imbalances in the first steps), independent of how often rows are written.
  /// Checkpoints: bytes written (rank 0), the running maxima, and leaving the file for a restart.
  long long bytes() const { return file_ ? file_->bytes() : 0; }
  std::vector<double> maxima() const { return {max_work_, max_imbalance_}; }
  void set_maxima(const std::vector<double>& m) { max_work_ = m.at(0), max_imbalance_ = m.at(1); }
  void Keep() { if (file_) file_->keep(); }
  double max_budget_error() const { return max_work_ > 0.0 ? max_imbalance_ / max_work_ : 0.0; }

 private:
  std::unique_ptr<store::AtomicFile> file_;
  double max_work_ = 0.0, max_imbalance_ = 0.0;
};

}  // namespace vibrotherm::io

#include "vibrotherm/io/energy_log.hpp"

#include <cmath>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

PetscErrorCode EnergyLog::Open(MPI_Comm comm, const std::string& path, long long resume_bytes) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, file_ = store::OpenAtomicFile(path, resume_bytes));
    if (resume_bytes < 0)
      file_->stream() << "t,work_source,kinetic,strain,radiated,interface_stored,dissipated,heat_deposited,"
                       "heat_content,heat_boundary_loss,budget_error,integrator_correction,heat_friction,heat_thermoelastic,work_thermal,"
                         "damped,heat_damping\n";
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyLog::Record(const EnergyRow& r, double* budget_error) {
  PetscFunctionBeginUser;
  max_work_ = std::max(max_work_, std::abs(r.work_source));
  const double imbalance = r.work_source + r.work_thermal - r.kinetic - r.strain - r.integrator_correction - r.radiated -
                           r.interface_stored - r.dissipated - r.damped;
  const double error = max_work_ > 0.0 ? imbalance / max_work_ : 0.0;
  max_imbalance_ = std::max(max_imbalance_, std::abs(imbalance));
  if (budget_error) *budget_error = error;
  if (file_)
    file_->stream() << r.t << ',' << r.work_source << ',' << r.kinetic << ',' << r.strain << ',' << r.radiated << ','
                    << r.interface_stored << ',' << r.dissipated << ',' << r.heat_deposited << ',' << r.heat_content
                    << ',' << r.heat_boundary_loss << ',' << error << ',' << r.integrator_correction << ',' << r.heat_friction << ','
                    << r.heat_thermoelastic << ',' << r.work_thermal << ',' << r.damped << ',' << r.heat_damping << '\n';
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyLog::Finish() {
  PetscFunctionBeginUser;
  if (file_) VibrothermCallIo(PETSC_COMM_SELF, file_->commit());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

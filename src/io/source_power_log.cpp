#include "vibrotherm/io/source_power_log.hpp"

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

PetscErrorCode SourcePowerLog::Open(MPI_Comm comm, const std::string& path, long long resume_bytes) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  opened_ = true;
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, file_ = store::OpenAtomicFile(path, resume_bytes));
    file_->stream().precision(12);
    if (resume_bytes < 0)
      file_->stream() << "t_start,t_end,periods,frequency,amplitude,input_power,friction_power,damping_power,"
                         "radiated_power,efficiency\n";
  }
  PetscFunctionReturn(0);
}

void SourcePowerLog::Record(const SourcePowerRow& r) {
  if (!file_) return;
  std::ostream& out = file_->stream();
  out << r.t_start << ',' << r.t_end << ',' << r.periods << ',' << r.frequency << ',' << r.amplitude << ',' << r.input
      << ',' << r.friction << ',' << r.damping << ',' << r.radiated << ',';
  // No input (the source stopped, the waves ring down): no efficiency, nan for every CSV reader.
  if (r.input > 0.0) out << r.efficiency();
  else out << "nan";
  out << '\n';
}

PetscErrorCode SourcePowerLog::Finish() {
  PetscFunctionBeginUser;
  if (file_) VibrothermCallIo(PETSC_COMM_SELF, file_->commit());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

#include "vibrotherm/io/crack_state_log.hpp"

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

PetscErrorCode CrackStateLog::Open(MPI_Comm comm, const std::string& path) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  VibrothermCallCpp(PETSC_COMM_SELF, file_ = std::make_unique<AtomicFile>(path));
  file_->stream().precision(9);
  file_->stream() << "t,crack,xi,x,y,a,b,N,T,state,power,W\n";
  PetscFunctionReturn(0);
}

void CrackStateLog::Record(double t, const std::vector<interface::CrackCellRecord>& records) {
  if (!file_) return;
  std::ostream& out = file_->stream();
  for (const interface::CrackCellRecord& r : records)
    out << t << ',' << r.crack + 1 << ',' << r.xi << ',' << r.x << ',' << r.y << ',' << r.a << ',' << r.b << ','
        << r.N << ',' << r.T << ',' << contact::to_string(r.state) << ',' << r.power << ',' << r.W << '\n';
}

PetscErrorCode CrackStateLog::Finish() {
  PetscFunctionBeginUser;
  if (file_) VibrothermCallCpp(PETSC_COMM_SELF, file_->commit());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

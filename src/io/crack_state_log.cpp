#include "vibrotherm/io/crack_state_log.hpp"

#include <charconv>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

PetscErrorCode CrackStateLog::Open(MPI_Comm comm, const std::string& path, long long resume_bytes) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  VibrothermCallCpp(PETSC_COMM_SELF, file_ = store::OpenAtomicFile(path, resume_bytes));
  if (resume_bytes < 0) file_->stream() << "t,crack,xi,s1,s2,x,y,z,a,b,b2,N,T,T2,state,power,W\n";
  PetscFunctionReturn(0);
}

namespace {

/// x as %.9g (what the stream's precision(9) wrote), without a locale-aware stream.
void Append(std::string* line, double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof(text), x, std::chars_format::general, 9).ptr;
  line->append(text, end);
  line->push_back(',');
}

}  // namespace

void CrackStateLog::Record(double t, const std::vector<interface::CrackCellRecord>& records) {
  if (!file_) return;
  // One formatted block per record time: ostream insertion on rank 0 was a tenth of a
  // wave step (the other ranks wait for it in the next reduction).
  std::string& block = block_;
  block.clear();
  for (const interface::CrackCellRecord& r : records) {
    for (const double x : {t, static_cast<double>(r.crack + 1), r.xi, r.s1, r.s2, r.x, r.y, r.z, r.a, r.b, r.b2, r.N,
                           r.T, r.T2})
      Append(&block, x);
    block.append(contact::to_string(r.state));
    block.push_back(',');
    Append(&block, r.power);
    Append(&block, r.W);
    block.back() = '\n';
  }
  file_->stream().write(block.data(), static_cast<std::streamsize>(block.size()));
}

PetscErrorCode CrackStateLog::Finish() {
  PetscFunctionBeginUser;
  if (file_) VibrothermCallIo(PETSC_COMM_SELF, file_->commit());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

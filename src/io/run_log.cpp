#include "vibrotherm/io/run_log.hpp"

#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <memory>

#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {
namespace {

struct Log {
  PetscErrorCode (*original)(FILE*, const char[], va_list) = nullptr;
  std::string held;
  std::unique_ptr<store::AtomicFile> file;
};
Log& TheLog() {
  static Log log;
  return log;
}

PetscErrorCode TeeVFPrintf(FILE* fd, const char format[], va_list args) {
  Log& log = TheLog();
  if (fd == PETSC_STDOUT || fd == PETSC_STDERR) {
    char buffer[8192];
    va_list copy;
    va_copy(copy, args);
    std::vsnprintf(buffer, sizeof(buffer), format, copy);
    va_end(copy);
    if (log.file) log.file->stream() << buffer << std::flush;
    else log.held += buffer;
  }
  return (*log.original)(fd, format, args);
}

}  // namespace

PetscErrorCode RunLogInstall() {
  PetscFunctionBeginUser;
  Log& log = TheLog();
  log.original = PetscVFPrintf;
  PetscVFPrintf = TeeVFPrintf;
  PetscFunctionReturn(0);
}

PetscErrorCode RunLogOpen(MPI_Comm comm, const std::string& path) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  Log& log = TheLog();
  VibrothermCallCpp(PETSC_COMM_SELF, log.file = std::make_unique<store::AtomicFile>(path));
  log.file->stream() << log.held << std::flush;
  log.held.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode RunLogPublish() {
  PetscFunctionBeginUser;
  Log& log = TheLog();
  // Rank 0 writes the log; a failure there ends every rank (a runtime failure).
  if (log.file) VibrothermCallIo(PETSC_COMM_SELF, log.file->publish_open());
  PetscFunctionReturn(0);
}

PetscErrorCode RunLogClose() {
  PetscFunctionBeginUser;
  Log& log = TheLog();
  if (log.original) PetscVFPrintf = log.original;
  if (log.file) VibrothermCallIo(PETSC_COMM_SELF, log.file->commit());
  log.file.reset();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

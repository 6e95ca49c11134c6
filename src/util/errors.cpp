#include "vibrotherm/util/errors.hpp"

#include <cstdio>

namespace vibrotherm {
namespace {

bool IsUserError(PetscErrorCode n) { return n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_FILE_OPEN; }

PetscErrorCode UserErrorHandler(MPI_Comm comm, int line, const char* fun, const char* file, PetscErrorCode n,
                                PetscErrorType p, const char* mess, void* ctx) {
  if (!IsUserError(n)) return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, ctx);
  if (p == PETSC_ERROR_INITIAL) {
    PetscMPIInt rank = 0;
    // Input is checked on every rank of comm: rank 0 of comm speaks for all.
    if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &rank);
    if (rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", static_cast<const char*>(ctx), mess ? mess : "(no message)");
      std::fflush(stderr);
    }
  }
  return n;
}

}  // namespace

PetscErrorCode PushUserErrorHandler(const char* program) {
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(UserErrorHandler, const_cast<char*>(program)));
  PetscFunctionReturn(0);
}

int ExitCode(PetscErrorCode ierr) {
  if (ierr == 0) return 0;
  return IsUserError(ierr) ? 2 : 1;
}

}  // namespace vibrotherm

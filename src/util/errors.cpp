#include "vibrotherm/util/errors.hpp"

#include <cctype>
#include <cstdio>
#include <sstream>
#include <string>

namespace vibrotherm {
namespace {

bool IsUserError(PetscErrorCode n) { return n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_FILE_OPEN; }

/// PETSc's messages about a value it cannot parse, which do not name the option.
struct ValueMessage {
  const char *head, *tail, *expected;
};
const ValueMessage kValueMessages[] = {
    {"Input string ", " has no numeric value", "a number"},
    {"Input string ", " has no integer value", "an integer"},
    {"Unknown logical value: ", "", "true or false (1|0|yes|no)"},
};

/// When mess is one of kValueMessages about X: "<options whose value, or one of
/// its comma-separated entries, is X>: expected ..., got 'X'"; else "".
std::string UnparsedValueOption(const char* mess) {
  const std::string m = mess ? mess : "";
  std::string value;
  const char* expected = nullptr;
  for (const ValueMessage& v : kValueMessages) {
    const std::string head = v.head, tail = v.tail;
    const std::size_t a = m.find(head);
    if (a == std::string::npos) continue;
    const std::size_t b = tail.empty() ? m.size() : m.find(tail, a + head.size());
    if (b == std::string::npos) continue;
    value = m.substr(a + head.size(), b - a - head.size());
    expected = v.expected;
    break;
  }
  if (!expected || value.empty()) return "";
  char* all = nullptr;
  if (PetscOptionsGetAll(nullptr, &all) || !all) return "";
  std::istringstream words(all);
  PetscFree(all);
  std::string word, option, names;
  while (words >> word) {
    if (word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1])) && word[1] != '.' &&
        word != value) {
      option = word;
      continue;
    }
    std::istringstream entries(word);
    bool holds = false;
    for (std::string entry; std::getline(entries, entry, ',');) holds = holds || entry == value;
    if (!option.empty() && holds) names += (names.empty() ? "" : ", ") + option;
  }
  return names.empty() ? "" : names + ": expected " + expected + ", got '" + value + "'";
}

PetscErrorCode UserErrorHandler(MPI_Comm comm, int line, const char* fun, const char* file, PetscErrorCode n,
                                PetscErrorType p, const char* mess, void* ctx) {
  if (!IsUserError(n) && p == PETSC_ERROR_INITIAL) {
    const std::string option = UnparsedValueOption(mess);
    if (!option.empty()) {  // a user error after all: every rank reads the options, every rank gets here
      PetscMPIInt rank = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      if (rank == 0) std::fprintf(stderr, "%s: error: %s\n", static_cast<const char*>(ctx), option.c_str());
      return PETSC_ERR_USER_INPUT;
    }
  }
  if (!IsUserError(n)) {
    // A runtime failure may be seen by one rank only: unwinding would leave the
    // others waiting in a collective call (HDF5 flushes, reductions). One line,
    // then the whole job ends; outputs stay under their .partial names.
    if (p == PETSC_ERROR_INITIAL) {
      std::fprintf(stderr, "%s: error: %s (%s, %s:%d)\n", static_cast<const char*>(ctx), mess ? mess : "(no message)",
                   fun ? fun : "?", file ? file : "?", line);
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    return n;
  }
  if (p == PETSC_ERROR_INITIAL) {
    PetscMPIInt rank = 0, size = 1, world = 1;
    // Input is checked on every rank of comm: rank 0 of comm speaks for all.
    if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &rank), MPI_Comm_size(comm, &size);
    MPI_Comm_size(MPI_COMM_WORLD, &world);
    if (rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", static_cast<const char*>(ctx), mess ? mess : "(no message)");
      std::fflush(stderr);
    }
    // Found by some ranks only (a file on rank 0): the others would wait forever.
    if (size < world) MPI_Abort(MPI_COMM_WORLD, 2);
  }
  return n;
}

}  // namespace

PetscErrorCode PushUserErrorHandler(const char* program) {
  PetscFunctionBeginUser;
  static std::string name;  // PETSc keeps the context pointer for the whole run
  name = program;
  PetscCall(PetscPushErrorHandler(UserErrorHandler, name.data()));
  PetscFunctionReturn(0);
}

int ExitCode(PetscErrorCode ierr) {
  if (ierr == 0) return 0;
  return IsUserError(ierr) ? 2 : 1;
}

}  // namespace vibrotherm

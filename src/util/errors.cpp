#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/stop_signals.hpp"

#include <dlfcn.h>
#include <hdf5.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace vibrotherm {
namespace {

/// The handler's context (PETSc keeps the pointer for the whole run).
struct HandlerContext {
  std::string program;
  bool debug = false;  ///< -debug: PETSc's trace after the line, MPI_Abort's banner, HDF5's diagnostics
  std::string writing;  ///< the output file being written (WritingFile), "" when none
};

HandlerContext g_context;  // the one handler's context: WritingFile and the handler share it

/// A runtime failure's line: the file being written and why it failed, when known.
std::string RuntimeFailure(const char* mess) {
  const std::string what = mess ? mess : "(no message)";
  std::string file = g_context.writing;
  if (file.empty()) {  // elsewhere (a CSV, our own HDF5 writers name their file): is the output's disk full?
    const std::string lock = stop_signals::LockPath();
    file = lock.empty() ? "" : lock;
    const std::string reason = file.empty() ? "" : WriteFailureReason(file);
    const bool full = reason.rfind("no space", 0) == 0 && what.find("no space") == std::string::npos;
    return full ? what + "; " + reason + " in " + std::filesystem::path(file).parent_path().string() : what;
  }
  const std::string reason = WriteFailureReason(file);
  return "writing " + file + (reason.empty() ? "" : ": " + reason) + " (" + what + ")";
}

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

/// The options whose value, or one of its comma-separated entries, is `value`
/// ("-a, -b"; "" when none).
std::string OptionsHolding(const std::string& value) {
  std::string all;
  if (value.empty() || AllOptions(&all) || all.empty()) return "";
  std::istringstream words(all);
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
  return names;
}

/// When mess is one of kValueMessages about X: "<options holding X>: expected ...,
/// got 'X'"; else "".
std::string UnparsedValueOption(const char* mess) {
  const std::string m = mess ? mess : "";
  for (const ValueMessage& v : kValueMessages) {
    const std::string head = v.head, tail = v.tail;
    const std::size_t a = m.find(head);
    if (a == std::string::npos) continue;
    const std::size_t b = tail.empty() ? m.size() : m.find(tail, a + head.size());
    if (b == std::string::npos) continue;
    const std::string value = m.substr(a + head.size(), b - a - head.size());
    const std::string names = OptionsHolding(value);
    return names.empty() ? "" : names + ": expected " + v.expected + ", got '" + value + "'";
  }
  return "";
}

/// PETSc's "unknown type" errors (Unknown TSAdapt type "foo" given, Unable to find
/// requested KSP type foo) about a value an option holds: "<option>: unknown value
/// 'foo' (PETSc: ...)"; else "".
std::string UnknownTypeOption(const char* mess) {
  std::istringstream words(mess ? mess : "");
  for (std::string word; words >> word;) {
    const std::size_t a = word.find_first_not_of("\"'"), b = word.find_last_not_of("\"':,.");
    if (a == std::string::npos || b == std::string::npos || b < a) continue;
    const std::string value = word.substr(a, b - a + 1), names = OptionsHolding(value);
    if (!names.empty()) return names + ": unknown value '" + value + "' (PETSc: " + mess + ")";
  }
  return "";
}

/// Ends every rank of the job at once with `code`. Open MPI's MPI_Abort prints a
/// seven-line banner by design (even serially); its ompi_mpi_abort, which
/// MPI_Abort calls after the banner, kills the job the same way without it. Looked
/// up at run time, so other MPI libraries get their MPI_Abort.
[[noreturn]] void EndJob(int code, bool debug) {
  stop_signals::RemoveLockNow();  // the next run into the directory needs no takeover
  using Abort = int (*)(MPI_Comm, int);
  const auto quiet = reinterpret_cast<Abort>(dlsym(RTLD_DEFAULT, "ompi_mpi_abort"));
  if (quiet && !debug) quiet(MPI_COMM_WORLD, code);
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

PetscErrorCode UserErrorHandler(MPI_Comm comm, int line, const char* fun, const char* file, PetscErrorCode n,
                                PetscErrorType p, const char* mess, void* ctx) {
  const HandlerContext& context = *static_cast<const HandlerContext*>(ctx);
  const char* program = context.program.c_str();
  if (context.debug) PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, nullptr);
  if (!IsUserError(n) && p == PETSC_ERROR_INITIAL) {
    const std::string option = n == PETSC_ERR_ARG_UNKNOWN_TYPE ? UnknownTypeOption(mess) : UnparsedValueOption(mess);
    if (!option.empty()) {  // a user error after all: every rank reads the options, every rank gets here
      PetscMPIInt rank = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      if (rank == 0) std::fprintf(stderr, "%s: error: %s\n", program, option.c_str());
      return PETSC_ERR_USER_INPUT;
    }
  }
  if (!IsUserError(n)) {
    // A runtime failure may be seen by one rank only: unwinding would leave the
    // others waiting in a collective call (HDF5 flushes, reductions). One line,
    // then the whole job ends; outputs stay under their .partial names (a
    // checkpoint's restart needs them).
    if (p == PETSC_ERROR_INITIAL) {
      std::fprintf(stderr, "%s: error: %s (%s, %s:%d)\n", program, RuntimeFailure(mess).c_str(), fun ? fun : "?",
                   file ? file : "?", line);
      std::fflush(stderr);
      EndJob(1, context.debug);
    }
    return n;
  }
  if (p == PETSC_ERROR_INITIAL) {
    PetscMPIInt rank = 0, size = 1, world = 1;
    // Input is checked on every rank of comm: rank 0 of comm speaks for all.
    if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &rank), MPI_Comm_size(comm, &size);
    MPI_Comm_size(MPI_COMM_WORLD, &world);
    if (rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", program, mess ? mess : "(no message)");
      std::fflush(stderr);
    }
    // Found by some ranks only (a file on rank 0): the others would wait forever.
    if (size < world) EndJob(2, context.debug);
  }
  return n;
}

}  // namespace

PetscErrorCode PushUserErrorHandler(const char* program) {
  PetscFunctionBeginUser;
  HandlerContext& context = g_context;  // PETSc keeps the context pointer for the whole run
  context.program = program;
  PetscCall(PetscPushErrorHandler(UserErrorHandler, &context));
  bool debug = false;  // read under the handler: a bad value is one line, exit 2
  PetscCall(OptionFlag(nullptr, "-debug", &debug));
  context.debug = debug;
  // HDF5 prints its error stack (~20 lines) on every failed call, even those the
  // program reports itself in one line: only with -debug.
  if (!debug) PetscCallExternal(H5Eset_auto2, H5E_DEFAULT, nullptr, nullptr);
  PetscFunctionReturn(0);
}

void PrintOneLineError(const char* program, const std::string& message) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::fprintf(stderr, "%s: error: %s\n", program, message.c_str());
}

int ExitCode(PetscErrorCode ierr) {
  if (ierr == 0) return 0;
  return IsUserError(ierr) ? 2 : 1;
}

WritingFile::WritingFile(const std::string& path) : previous_(g_context.writing) { g_context.writing = path; }

WritingFile::~WritingFile() { g_context.writing = previous_; }


}  // namespace vibrotherm

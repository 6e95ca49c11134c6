// vibrotherm: vibrothermography of cracked solids.
//
// Builds the specimen, then either runs the scene (waves, crack contact, heat;
// coupling/driver.hpp) or, with -modes, solves for its natural modes.
#include <slepcsys.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <string>
#include <vector>

#include "vibrotherm/options/option_database.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/stop_signals.hpp"
#include "run.hpp"

namespace {

/// While PETSc starts with -help it prints its version banner, its generic options and
/// its device options (80 lines before vibrotherm's own): dropped.
PetscErrorCode DropPetscHelp(MPI_Comm, const char[], ...) { return 0; }

const char kIntro[] =
    "vibrotherm: vibrothermography of cracked solids (elastic waves, crack contact with friction, heat, an IR "
    "camera) in 2D plane strain or in a 3D box.\n"
    "Usage: vibrotherm -options_file FILE [-name value ...]   (options after the file override it)\n"
    "       scripts/run FILE [-name value ...]                 (build, run on all cores, plots)\n"
    "Every option, by task, with <default : value now>:\n";

}  // namespace

int main(int argc, char** argv) {
  // The GNU spellings too: --help and --version mean -help and -version.
  static char help[] = "-help", version[] = "-version";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0) argv[i] = help;
    if (std::strcmp(argv[i], "--version") == 0) argv[i] = version;
  }
  const std::vector<std::string> command_line(argv + 1, argv + argc);
  // PETSc reads options files inside PetscInitialize, where a missing file or a
  // malformed line is a 20-line trace and an MPI_Abort, and resolves a file's
  // includes relative to the working directory: the files are read here instead
  // (includes relative to the including file), with MPI up (PETSc then leaves
  // MPI_Finalize to us), and PETSc gets their options in their place.
  MPI_Init(&argc, &argv);
  static std::vector<std::string> expanded;  // PETSc keeps pointers into argv
  try {
    expanded = vibrotherm::options::expand_options_files(command_line);
  } catch (const std::exception& e) {
    vibrotherm::PrintOneLineError("vibrotherm", e.what());
    MPI_Finalize();
    return 2;
  }
  static std::vector<char*> words = {argv[0]};
  for (std::string& word : expanded) words.push_back(word.data());
  words.push_back(nullptr);
  int petsc_argc = static_cast<int>(words.size()) - 1;
  char** petsc_argv = words.data();
  const bool asks_help = std::find(expanded.begin(), expanded.end(), "-help") != expanded.end();
  if (asks_help) PetscHelpPrintf = DropPetscHelp;
  PetscCall(SlepcInitialize(&petsc_argc, &petsc_argv, nullptr, nullptr));
  PetscHelpPrintf = PetscHelpPrintfDefault;
  if (asks_help) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", kIntro));
  // Output piped into a reader that stopped (vibrotherm ... | head): end quietly, as
  // any command does, not with PETSc's trace of a "caught signal".
  std::signal(SIGPIPE, SIG_DFL);
  // Ctrl-C, SIGTERM, SIGUSR1 from here on (PETSc has installed its own handlers by now).
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  vibrotherm::stop_signals::Install(rank);
  int status = 0;
  PetscErrorCode ierr = vibrotherm::PushUserErrorHandler("vibrotherm");
  if (!ierr) ierr = vibrotherm::app::Run(PETSC_COMM_WORLD, command_line, &status);
  PetscCall(SlepcFinalize());
  MPI_Finalize();
  return ierr ? vibrotherm::ExitCode(ierr) : status;
}

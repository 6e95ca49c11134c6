// vibrotherm: vibrothermography of cracked solids.
//
// Builds the specimen, then either runs the scene (waves, crack contact, heat;
// coupling/driver.hpp) or, with -modes, solves for its natural modes.
#include <slepcsys.h>

#include <csignal>
#include <cstring>
#include <string>
#include <vector>

#include "vibrotherm/options/option_database.hpp"
#include "vibrotherm/util/errors.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  // The GNU spellings too: --help and --version mean -help and -version.
  static char help[] = "-help", version[] = "-version";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0) argv[i] = help;
    if (std::strcmp(argv[i], "--version") == 0) argv[i] = version;
  }
  const std::vector<std::string> command_line(argv + 1, argv + argc);
  // PETSc reads the options files inside PetscInitialize, where a missing file
  // or a malformed line is a 20-line trace and an MPI_Abort: checked first, with
  // MPI up (PETSc then leaves MPI_Finalize to us).
  MPI_Init(&argc, &argv);
  const std::string options_file_error = vibrotherm::options::options_file_error(command_line);
  if (!options_file_error.empty()) {
    vibrotherm::PrintOneLineError("vibrotherm", options_file_error);
    MPI_Finalize();
    return 2;
  }
  PetscCall(SlepcInitialize(&argc, &argv, nullptr,
                            "vibrotherm: ultrasonic waves, crack contact (MMD) and frictional heating.\n"
                            "Options files: -options_file options/paper.opts. Full list: -help.\n"));
  // Output piped into a reader that stopped (vibrotherm ... | head): end quietly, as
  // any command does, not with PETSc's trace of a "caught signal".
  std::signal(SIGPIPE, SIG_DFL);
  int status = 0;
  PetscErrorCode ierr = vibrotherm::PushUserErrorHandler("vibrotherm");
  if (!ierr) ierr = vibrotherm::app::Run(PETSC_COMM_WORLD, command_line, &status);
  PetscCall(SlepcFinalize());
  MPI_Finalize();
  return ierr ? vibrotherm::ExitCode(ierr) : status;
}

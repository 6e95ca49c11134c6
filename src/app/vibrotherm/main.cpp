// vibrotherm: vibrothermography of cracked solids.
//
// Builds the specimen, then either runs the scene (waves, crack contact, heat;
// coupling/driver.hpp) or, with -modes, solves for its natural modes.
#include <slepcsys.h>

#include "vibrotherm/util/errors.hpp"
#include "run.hpp"

int main(int argc, char** argv) {
  PetscCall(SlepcInitialize(&argc, &argv, nullptr,
                            "vibrotherm: ultrasonic waves, crack contact (MMD) and frictional heating.\n"
                            "Options files: -options_file options/paper.opts. Full list: -help.\n"));
  PetscCall(vibrotherm::PushUserErrorHandler("vibrotherm"));
  const PetscErrorCode ierr = vibrotherm::app::Run(PETSC_COMM_WORLD);
  PetscCall(SlepcFinalize());
  return vibrotherm::ExitCode(ierr);
}

// vibrotherm: vibrothermography of cracked solids.
//
// Today this builds the specimen (mesh, crack split, distribution) and writes
// the mesh outputs; the wave, interface and heat stages follow (issues 4-6).
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

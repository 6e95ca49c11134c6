#pragma once

#include <petscsys.h>

namespace vibrotherm::app {
/// The whole program after PetscInitialize.
PetscErrorCode Run(MPI_Comm comm);
}  // namespace vibrotherm::app

#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vibrotherm::app {
/// The whole program after PetscInitialize.
/// *status: the exit status besides errors (128 + the signal that stopped a run for a restart).
PetscErrorCode Run(MPI_Comm comm, const std::vector<std::string>& command_line, int* status);
}  // namespace vibrotherm::app

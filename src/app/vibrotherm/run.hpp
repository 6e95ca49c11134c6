#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vibrotherm::app {
/// The whole program after PetscInitialize.
PetscErrorCode Run(MPI_Comm comm, const std::vector<std::string>& command_line);
}  // namespace vibrotherm::app

// The -crack_law and -contact_* options, shared by vibrotherm and vibrotherm-contact.
#pragma once

#include <petscsys.h>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm {

/// Reads the options into params (defaults are params' values on entry),
/// listing them in -help; validates, naming the offending option.
PetscErrorCode ReadContactOptions(MPI_Comm comm, contact::ContactParameters& params);

}  // namespace vibrotherm

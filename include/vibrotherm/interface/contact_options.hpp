// The simulator's reader of the declared contact options (-crack_law, -contact_*,
// -crack_<law>_*, -material_nu); vibrotherm-contact reads the same declarations
// without PETSc (src/app/contact).
#pragma once

#include <petscsys.h>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm {

/// Reads the declared contact options (contact::contact_parameters()) into
/// params: an option not given keeps its value on entry (the declared default
/// for a default-constructed params). Retired names and bad values are user
/// errors naming the option; -help lists every option with help and default.
PetscErrorCode ReadContactOptions(MPI_Comm comm, contact::ContactParameters& params, OptionValues* values = nullptr);

}  // namespace vibrotherm

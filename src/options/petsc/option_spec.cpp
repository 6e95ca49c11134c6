#include "vibrotherm/options/petsc/option_spec.hpp"

#include <cmath>

namespace vibrotherm {

PetscErrorCode CheckOptionRange(MPI_Comm comm, const contact::ParameterSpec& spec, double value) {
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(value), comm, PETSC_ERR_USER_INPUT, "%s must be finite, got %g", spec.name.c_str(), value);
  PetscCheck(spec.range.contains(value), comm, PETSC_ERR_USER_INPUT, "%s %s, got %g", spec.name.c_str(),
             spec.range.rule().c_str(), value);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

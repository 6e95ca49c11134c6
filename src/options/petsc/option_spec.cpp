#include "vibrotherm/options/petsc/option_spec.hpp"

#include <cmath>
#include <string>

namespace vibrotherm {

PetscErrorCode CheckOptionRange(MPI_Comm comm, const contact::ParameterSpec& spec, double value) {
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(value), comm, PETSC_ERR_USER_INPUT, "%s must be finite, got %g", spec.name.c_str(), value);
  const std::string unit = spec.unit.empty() ? "" : " " + spec.unit;  // "must be > 0 Hz"
  PetscCheck(spec.range.contains(value), comm, PETSC_ERR_USER_INPUT, "%s %s%s, got %g", spec.name.c_str(),
             spec.range.rule().c_str(), unit.c_str(), value);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

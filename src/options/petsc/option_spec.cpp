#include "vibrotherm/options/petsc/option_spec.hpp"

#include <cmath>
#include <sstream>
#include <string>

namespace vibrotherm {

PetscErrorCode CheckOptionRange(MPI_Comm comm, const contact::ParameterSpec& spec, double value) {
  PetscFunctionBeginUser;
  std::ostringstream shown;  // "got 0", not PETSc's "%g" of "got 0."
  shown << value;
  PetscCheck(std::isfinite(value), comm, PETSC_ERR_USER_INPUT, "%s must be finite, got %s", spec.name.c_str(),
             shown.str().c_str());
  const std::string unit = spec.unit.empty() ? "" : " " + spec.unit;  // "must be > 0 Hz"
  PetscCheck(spec.range.contains(value), comm, PETSC_ERR_USER_INPUT, "%s %s%s, got %s", spec.name.c_str(),
             spec.range.rule().c_str(), unit.c_str(), shown.str().c_str());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

#include "vibrotherm/options/petsc/option_spec.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "vibrotherm/util/errors.hpp"

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

std::string ShownReal(double value) {
  char text[64];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

std::string ShownInt(PetscInt value) { return std::to_string(value); }

std::string ShownFlag(bool value) { return value ? "TRUE" : "FALSE"; }

PetscErrorCode ReadTextChoice(PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& spec,
                              std::string* value) {
  PetscFunctionBeginUser;
  char text[256] = "";
  PetscBool given = PETSC_FALSE;
  PetscCall(PetscOptionsString(spec.name.c_str(), spec.describe().c_str(), nullptr, text, text, sizeof(text), &given));
  *value = given ? text : "";  // given without a value: the missing-value check names it later
  if (!value->empty()) VibrothermCallCpp(PetscOptionsObject->comm, contact::check_choice(spec, *value));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

#include "vibrotherm/options/petsc/option_list.hpp"

#include <sstream>
#include <string>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/contact/parameter_spec.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm {

PetscErrorCode OptionsRealList(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                               std::vector<double>* values, PetscBool* set, std::string* shown) {
  PetscFunctionBeginUser;
  std::ostringstream listed;
  listed.precision(17);
  for (std::size_t i = 0; i < values->size(); ++i) listed << (i ? "," : "") << (*values)[i];
  const std::string fallback = values->empty() ? "none" : listed.str();
  char text[4096];
  PetscBool given = PETSC_FALSE;
  PetscCall(PetscOptionsString(option, help, nullptr, fallback.c_str(), text, sizeof(text), &given));
  if (set) *set = given;
  if (shown) *shown = given ? text : fallback;
  if (!given) PetscFunctionReturn(0);
  // "-crack_center" alone (or with ""): PETSc gives an empty string.
  PetscCheck(text[0] != '\0', PetscOptionsObject->comm, PETSC_ERR_USER_INPUT, "%s: needs a value", option);
  values->clear();
  std::stringstream entries(text);
  std::string entry;
  VibrothermCallCpp(PetscOptionsObject->comm, {
    while (std::getline(entries, entry, ',')) values->push_back(contact::parse_real(entry, option));
  });
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

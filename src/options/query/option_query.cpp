#include "vibrotherm/options/query/option_query.hpp"

namespace vibrotherm {

PetscErrorCode OptionGiven(const char* prefix, const char* name, bool* given) {
  PetscFunctionBeginUser;
  PetscBool set = PETSC_FALSE;
  PetscCall(PetscOptionsHasName(nullptr, prefix, name, &set));
  *given = set;
  PetscFunctionReturn(0);
}

PetscErrorCode FirstOptionGiven(std::initializer_list<const char*> names, const char** given) {
  PetscFunctionBeginUser;
  *given = nullptr;
  for (const char* name : names) {
    bool set;
    PetscCall(OptionGiven(nullptr, name, &set));
    if (set && !*given) *given = name;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OptionText(const char* prefix, const char* name, std::string* value, bool* given) {
  PetscFunctionBeginUser;
  char text[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  PetscCall(PetscOptionsGetString(nullptr, prefix, name, text, sizeof text, &set));
  if (set) *value = text;
  if (given) *given = set;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReal(const char* prefix, const char* name, double* value, bool* given) {
  PetscFunctionBeginUser;
  PetscReal v = *value;
  PetscBool set = PETSC_FALSE;
  PetscCall(PetscOptionsGetReal(nullptr, prefix, name, &v, &set));
  if (set) *value = v;
  if (given) *given = set;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionInt(const char* prefix, const char* name, PetscInt* value, bool* given) {
  PetscFunctionBeginUser;
  PetscBool set = PETSC_FALSE;
  PetscCall(PetscOptionsGetInt(nullptr, prefix, name, value, &set));
  if (given) *given = set;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionFlag(const char* prefix, const char* name, bool* value, bool* given) {
  PetscFunctionBeginUser;
  PetscBool flag = *value ? PETSC_TRUE : PETSC_FALSE, set = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, prefix, name, &flag, &set));
  *value = flag;
  if (given) *given = set;
  PetscFunctionReturn(0);
}

PetscErrorCode AllOptions(std::string* text) {
  PetscFunctionBeginUser;
  char* all = nullptr;
  text->clear();
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  if (all) *text = all;
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

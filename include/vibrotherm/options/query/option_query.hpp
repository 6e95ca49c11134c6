// The one place outside the option readers that looks at PETSc's options database:
// whether an option was given and what it holds, for the checks that concern several
// options at once (a refusal of a combination, a warning that an option is not used,
// the dimension of a scene before its readers run) and for the run record. Module
// options are read by their modules' readers (PetscOptionsBegin blocks or declared
// parameters) into the Scene; nothing here declares an option or shows it in -help.
#pragma once

#include <petscsys.h>

#include <initializer_list>
#include <string>

namespace vibrotherm {

/// Whether `name` (with its dash) is given under `prefix` (null: none), on the command line or in a file.
PetscErrorCode OptionGiven(const char* prefix, const char* name, bool* given);
/// The first of `names` given (nullptr: none of them).
PetscErrorCode FirstOptionGiven(std::initializer_list<const char*> names, const char** given);
/// The value of `name` as text; *value is left alone when the option is not given.
PetscErrorCode OptionText(const char* prefix, const char* name, std::string* value, bool* given = nullptr);
/// The value of `name` as a number, an integer or a flag (PETSc's parsing; a bad value is PETSc's error);
/// *value is left alone when the option is not given.
PetscErrorCode OptionReal(const char* prefix, const char* name, double* value, bool* given = nullptr);
PetscErrorCode OptionInt(const char* prefix, const char* name, PetscInt* value, bool* given = nullptr);
PetscErrorCode OptionFlag(const char* prefix, const char* name, bool* value, bool* given = nullptr);
/// Every option given, as PETSc lists them ("-a 1 -b x").
PetscErrorCode AllOptions(std::string* text);

}  // namespace vibrotherm

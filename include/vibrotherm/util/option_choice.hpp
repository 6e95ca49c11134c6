// One helper for every choice option (-physics, -heat_mesh, -edge_top, ...):
// listed in -help with its values and real default (PetscOptionsEList), and an
// unknown value is a one-line user error naming the option and the values.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vibrotherm {

/// Inside PetscOptionsBegin/End: reads `option` as one of `names`; *index holds
/// the default on entry and the choice on return; *set (may be null) whether given.
PetscErrorCode OptionsChoice(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                             const std::vector<std::string>& names, PetscInt* index, PetscBool* set);

/// "a|b|c".
std::string JoinChoices(const std::vector<std::string>& names);

}  // namespace vibrotherm

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

/// A comma-separated list of `names` (one value or one per item): *indices is left alone
/// unless given; an unknown item is a one-line user error naming the option. shown (if not
/// null): the value as -help shows it (as typed, or the first name).
PetscErrorCode OptionsChoiceList(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                                 const std::vector<std::string>& names, std::vector<PetscInt>* indices,
                                 PetscBool* set, std::string* shown = nullptr);

/// OptionsChoice for an enum whose values are the indices of `names`.
template <class Enum>
PetscErrorCode OptionsChoiceEnum(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                                 const std::vector<std::string>& names, Enum* value) {
  PetscInt index = static_cast<PetscInt>(*value);
  PetscErrorCode ierr = OptionsChoice(PetscOptionsObject, option, help, names, &index, nullptr);
  if (!ierr) *value = static_cast<Enum>(index);
  return ierr;
}

/// "a|b|c".
std::string JoinChoices(const std::vector<std::string>& names);

}  // namespace vibrotherm

// List options (-crack_center x1,y1,..., -output_times t1,t2): read as text so
// that -help shows the real default ("none" when there is none, not whatever
// memory held), and parsed strictly: every entry a finite number, else one line
// naming the option.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vibrotherm {

/// Inside PetscOptionsBegin/End. values: the default on entry, the list on return; set: whether
/// given; shown (if not null): the list as -help shows it (as typed, or the default, or "none").
PetscErrorCode OptionsRealList(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                               std::vector<double>* values, PetscBool* set, std::string* shown = nullptr);

}  // namespace vibrotherm

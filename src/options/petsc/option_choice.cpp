#include "vibrotherm/options/petsc/option_choice.hpp"

#include <algorithm>

namespace vibrotherm {
namespace {

/// The index of `value` in `names`, or a one-line user error naming the option.
PetscErrorCode ChoiceIndex(MPI_Comm comm, const char* option, const std::string& value,
                           const std::vector<std::string>& names, PetscInt* index) {
  PetscFunctionBeginUser;
  const auto it = std::find(names.begin(), names.end(), value);
  PetscCheck(it != names.end(), comm, PETSC_ERR_USER_INPUT, "%s: unknown value '%s' (known: %s)", option,
             value.c_str(), JoinChoices(names).c_str());
  *index = static_cast<PetscInt>(it - names.begin());
  PetscFunctionReturn(0);
}

}  // namespace

std::string JoinChoices(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& n : names) joined += (joined.empty() ? "" : "|") + n;
  return joined;
}

PetscErrorCode OptionsChoice(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                             const std::vector<std::string>& names, PetscInt* index, PetscBool* set) {
  PetscFunctionBeginUser;
  // Checked before PetscOptionsEList, whose own error is a PETSc trace, not a user error.
  char value[256];
  PetscBool given = PETSC_FALSE;
  PetscCall(PetscOptionsGetString(PetscOptionsObject->options, PetscOptionsObject->prefix, option, value,
                                  sizeof(value), &given));
  PetscInt checked;
  if (given) PetscCall(ChoiceIndex(PetscOptionsObject->comm, option, value, names, &checked));
  std::vector<const char*> list;
  for (const std::string& n : names) list.push_back(n.c_str());
  const std::string text = std::string(help) + " (" + JoinChoices(names) + ")";
  PetscCall(PetscOptionsEList(option, text.c_str(), nullptr, list.data(), static_cast<PetscInt>(list.size()),
                              list[*index], index, set));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionsChoiceList(PetscOptionItems* PetscOptionsObject, const char* option, const char* help,
                                 const std::vector<std::string>& names, std::vector<PetscInt>* indices,
                                 PetscBool* set, std::string* shown) {
  PetscFunctionBeginUser;
  char value[1024] = "";
  PetscBool given = PETSC_FALSE;
  const std::string text = std::string(help) + " (" + JoinChoices(names) + ", one value or a comma-separated list)";
  // -help shows the first name, the default of a list not given.
  PetscCall(PetscOptionsString(option, text.c_str(), nullptr, names.front().c_str(), value, sizeof(value), &given));
  if (set) *set = given;
  if (shown) *shown = given ? value : names.front();
  if (!given) PetscFunctionReturn(0);
  indices->clear();
  std::string rest = value;
  for (std::size_t start = 0;;) {
    const std::size_t comma = rest.find(',', start);
    const std::string item = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    PetscInt index;
    PetscCall(ChoiceIndex(PetscOptionsObject->comm, option, item, names, &index));
    indices->push_back(index);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

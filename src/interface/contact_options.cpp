#include "vibrotherm/interface/contact_options.hpp"

#include <string>

#include "vibrotherm/contact/contact_parameter_list.hpp"
#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm {
namespace {

/// Retired names are refused, wherever they come from (command line or file).
PetscErrorCode RejectRenamedOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  for (const contact::RenamedOption& r : contact::renamed_contact_options()) {
    bool set;
    PetscCall(OptionGiven(nullptr, r.old_name, &set));
    PetscCheck(!set, comm, PETSC_ERR_USER_INPUT, "%s", contact::renamed_message(r).c_str());
  }
  PetscFunctionReturn(0);
}

/// One declared parameter. Read as text and parsed by the contact library, so
/// the simulator accepts exactly what vibrotherm-contact accepts; -help shows
/// the declared help, unit, range and default.
PetscErrorCode ReadParameter(MPI_Comm comm, PetscOptionItems* PetscOptionsObject, const contact::ContactParameter& p,
                             contact::ContactParameters& params, OptionValues* values) {
  PetscFunctionBeginUser;
  char value[PETSC_MAX_PATH_LEN] = "";
  PetscBool set = PETSC_FALSE;
  const contact::ParameterSpec& s = p.spec;
  PetscCall(PetscStrncpy(value, s.default_value.c_str(), sizeof(value)));
  PetscCall(PetscOptionsString(s.name.c_str(), s.describe().c_str(), nullptr, s.default_value.c_str(), value,
                               sizeof(value), &set));
  if (set) VibrothermCallCpp(comm, contact::assign(p, params, value));
  if (values) values->emplace(s.name, value);  // as -help shows it: as given, or the declared default
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ReadContactOptions(MPI_Comm comm, contact::ContactParameters& p, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(RejectRenamedOptions(comm));
  // vibrotherm-contact's one cell starts at -contact_a0; a crack's faces start at -crack_a0 and its
  // profile (interface/approach_profile): one name here, the other refused, not silently ignored.
  bool cell_a0;
  PetscCall(OptionGiven(nullptr, "-contact_a0", &cell_a0));
  PetscCheck(!cell_a0, comm, PETSC_ERR_USER_INPUT,
             "-contact_a0 is vibrotherm-contact's (one contact cell); the crack faces' initial approach in vibrotherm "
             "is -crack_a0 [m] (with -crack_a0_profile)");
  PetscOptionsBegin(comm, nullptr, "Crack contact law (PHYSICS.md section 3)", nullptr);
  for (const contact::ContactParameter& parameter : contact::contact_parameters())
    if (parameter.spec.name != "-contact_a0") PetscCall(ReadParameter(comm, PetscOptionsObject, parameter, p, values));
  PetscOptionsEnd();
  VibrothermCallCpp(comm, (void)contact::create_crack_law(p));  // validates; reads table files
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

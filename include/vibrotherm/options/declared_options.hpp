// Declared parameters (contact::Parameter) read from an OptionDatabase: the
// PETSc-free counterpart of reading them with PetscOptions* (same declarations,
// same parsing and checks, same messages).
#pragma once

#include <string>
#include <vector>

#include "vibrotherm/contact/parameter_spec.hpp"
#include "vibrotherm/options/option_database.hpp"

namespace vibrotherm::options {

/// "  -name <default>  help [unit] (rule)" for -help.
std::string help_line(const contact::ParameterSpec& spec);

/// The value given for spec.name; InputError "<name>: needs a value" for a
/// bare "-name".
std::optional<std::string> given_value(const OptionDatabase& db, const contact::ParameterSpec& spec);

/// InputError for the first name in db that is retired ("<old> was renamed:
/// use <new>") or not in known ("unknown option -x; did you mean -y?").
void reject_unknown(const OptionDatabase& db, const std::vector<std::string>& known,
                    const std::vector<contact::RenamedOption>& renamed);

/// Parses and checks the options of params given in db into target; the
/// others keep their value.
template <class Target>
void read_parameters(const OptionDatabase& db, const std::vector<contact::Parameter<Target>>& params,
                     Target& target) {
  for (const contact::Parameter<Target>& p : params)
    if (const auto text = given_value(db, p.spec)) contact::assign(p, target, *text);
}

template <class Target>
void append_names(std::vector<std::string>& names, const std::vector<contact::Parameter<Target>>& params) {
  for (const contact::Parameter<Target>& p : params) names.push_back(p.spec.name);
}

}  // namespace vibrotherm::options

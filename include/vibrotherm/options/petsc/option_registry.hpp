// Every option vibrotherm declares, gathered from the modules' declared lists
// (option_spec.hpp; the contact laws' contact::ParameterSpec lists). From it come the
// names the command line is checked against ("-crak_angle: did you mean -crack_angle?")
// and which options are flags (they need no value); PETSc's printer is captured only
// for the options of the PETSc objects vibrotherm creates (option_audit.hpp).
//
// A module's list is added where the modules meet: coupling::AddSceneOptions (the
// scene) and the application (its own options and -modes).
#pragma once

#include <string>
#include <vector>

#include "vibrotherm/contact/parameter_spec.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm {

class OptionRegistry {
 public:
  /// Adds a module's declared list.
  template <class Target>
  OptionRegistry& Add(const std::vector<OptionSpec<Target>>& list) {
    for (const OptionSpec<Target>& option : list) specs_.push_back(option.spec);
    return *this;
  }
  /// Adds declarations (the contact laws' parameters).
  OptionRegistry& Add(const std::vector<contact::ParameterSpec>& list);

  const std::vector<contact::ParameterSpec>& specs() const { return specs_; }
  /// Every declared name, sorted, each once.
  std::vector<std::string> names() const;
  /// The names of the options that take a value (all but flags), sorted.
  std::vector<std::string> names_with_values() const;

 private:
  std::vector<contact::ParameterSpec> specs_;
};

}  // namespace vibrotherm

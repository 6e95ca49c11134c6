// An option declared once, beside the object that owns it (issue 42 item 2, the model
// being contact::ParameterSpec): its name, help, unit, allowed range or values, and the
// field of the owner's options struct it fills, whose initial value is the default. A
// module lists its options (a std::vector<OptionSpec<ItsOptions>>, e.g.
// coupling::PeriodicOptionSpecs()); ReadOptionSpecs reads the list in one
// PetscOptionsBegin block. From the one declaration come:
//   - the reading (PETSc's parsers: what PetscOptionsReal/Int/Bool accept);
//   - the range check and its one-line error "<name> must be in (0, 1), got 2" (or "must be
//     finite, got inf");
//   - -help: "help [unit] (the range, or the values)" with the default.
// The typo check and the run record still learn the names and values from -help's lines
// (option_audit.hpp), which ReadOptionSpecs prints like any PETSc options block.
#pragma once

#include <petscsys.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/contact/parameter_spec.hpp"
#include "vibrotherm/options/petsc/option_choice.hpp"
#include "vibrotherm/options/petsc/option_list.hpp"

namespace vibrotherm {

template <class Target>
struct OptionSpec {
  contact::ParameterSpec spec;  ///< name, help, unit, type, range, choices (the default is the field's value)
  /// Reads spec.name into its field of target (inside PetscOptionsBegin/End) and checks it.
  std::function<PetscErrorCode(PetscOptionItems*, const contact::ParameterSpec&, Target*)> read;
};

/// A one-line user error unless value is finite ("<name> must be finite, got inf") and lies in
/// spec.range ("<name> <rule> <unit>, got <value>": "-modes_target_frequency must be > 0 Hz, got -5").
PetscErrorCode CheckOptionRange(MPI_Comm comm, const contact::ParameterSpec& spec, double value);

/// A real option [unit] in range.
template <class Target>
OptionSpec<Target> RealOption(const char* name, double Target::*field, contact::Range range, const char* unit,
                              const char* help) {
  return {{name, help, unit, contact::ParameterType::Real, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            PetscCall(PetscOptionsReal(s.name.c_str(), s.describe().c_str(), nullptr, t->*field, &(t->*field), nullptr));
            return CheckOptionRange(PetscOptionsObject->comm, s, t->*field);
          }};
}

/// A real option whose default is derived elsewhere (the field's initial value stands for "not
/// given", e.g. -final_time: the source's duration): a value given must lie in range.
template <class Target>
OptionSpec<Target> GivenRealOption(const char* name, double Target::*field, contact::Range range, const char* unit,
                                   const char* help) {
  return {{name, help, unit, contact::ParameterType::Real, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            PetscBool given = PETSC_FALSE;
            PetscCall(PetscOptionsReal(s.name.c_str(), s.describe().c_str(), nullptr, t->*field, &(t->*field), &given));
            return given ? CheckOptionRange(PetscOptionsObject->comm, s, t->*field) : PetscErrorCode(0);
          }};
}

/// A list x1,x2,... [unit] of reals, each in range (the field's initial value is the default).
template <class Target>
OptionSpec<Target> RealListOption(const char* name, std::vector<double> Target::*field, contact::Range range,
                                  const char* unit, const char* help) {
  return {{name, help, unit, contact::ParameterType::RealList, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            PetscCall(OptionsRealList(PetscOptionsObject, s.name.c_str(), s.describe().c_str(), &(t->*field), nullptr));
            for (double value : t->*field) PetscCall(CheckOptionRange(PetscOptionsObject->comm, s, value));
            return PetscErrorCode(0);
          }};
}

/// A text option (a file name, a face name: its owner checks what it names).
template <class Target>
OptionSpec<Target> TextOption(const char* name, std::string Target::*field, const char* help) {
  return {{name, help, "", contact::ParameterType::Text, "", contact::Range::any(), {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            char text[PETSC_MAX_PATH_LEN];
            PetscCall(PetscStrncpy(text, (t->*field).c_str(), sizeof(text)));
            PetscCall(PetscOptionsString(s.name.c_str(), s.help.c_str(), nullptr, text, text, sizeof(text), nullptr));
            t->*field = text;
            return PetscErrorCode(0);
          }};
}

/// Reads a text that, when given, must be one of spec.choices (an error naming the option and
/// the values otherwise); *value: "" when not given.
PetscErrorCode ReadTextChoice(PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& spec,
                              std::string* value);

/// One of `choices` kept as its text, "" when not given (-heat_bc sink: a default that depends
/// on the scene). field: where in Target it goes (a function, so an array's entry can be one).
template <class Target>
OptionSpec<Target> TextChoiceOption(const std::string& name, std::function<std::string*(Target*)> field,
                                    std::vector<std::string> choices, const char* help) {
  return {{name, help, "", contact::ParameterType::Choice, "", contact::Range::any(), std::move(choices)},
          [field](PetscOptionItems* items, const contact::ParameterSpec& s, Target* t) {
            return ReadTextChoice(items, s, field(t));
          }};
}

/// An integer option in range.
template <class Target>
OptionSpec<Target> IntOption(const char* name, PetscInt Target::*field, contact::Range range, const char* help) {
  return {{name, help, "", contact::ParameterType::Integer, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            PetscCall(PetscOptionsInt(s.name.c_str(), s.describe().c_str(), nullptr, t->*field, &(t->*field), nullptr));
            return CheckOptionRange(PetscOptionsObject->comm, s, static_cast<double>(t->*field));
          }};
}

/// An on/off flag ("-name", "-name 0", "-name false").
template <class Target>
OptionSpec<Target> FlagOption(const char* name, bool Target::*field, const char* help) {
  return {{name, help, "", contact::ParameterType::Flag, "", contact::Range::any(), {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            PetscBool value = t->*field ? PETSC_TRUE : PETSC_FALSE;
            PetscCall(PetscOptionsBool(s.name.c_str(), s.help.c_str(), nullptr, value, &value, nullptr));
            t->*field = value;
            return PetscErrorCode(0);
          }};
}

/// One of `names`, stored as their index in an enum (or a bool: names {false's, true's}).
template <class Target, class Enum>
OptionSpec<Target> ChoiceOption(const char* name, Enum Target::*field, std::vector<std::string> names,
                                const char* help) {
  return {{name, help, "", contact::ParameterType::Choice, "", contact::Range::any(), names},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t) {
            PetscInt index = static_cast<PetscInt>(t->*field);
            PetscCall(OptionsChoice(PetscOptionsObject, s.name.c_str(), s.help.c_str(), s.choices, &index, nullptr));
            t->*field = static_cast<Enum>(index);
            return PetscErrorCode(0);
          }};
}

/// An option of a nested struct (Outer::*member) read as part of Outer's list.
template <class Outer, class Inner>
OptionSpec<Outer> NestedOption(Inner Outer::*member, const OptionSpec<Inner>& inner) {
  return {inner.spec, [member, read = inner.read](PetscOptionItems* items, const contact::ParameterSpec& s, Outer* t) {
            return read(items, s, &(t->*member));
          }};
}

/// Reads every option of `specs` into target in one options block titled `title`. Collective.
template <class Target>
PetscErrorCode ReadOptionSpecs(MPI_Comm comm, const char* title, const std::vector<OptionSpec<Target>>& specs,
                               Target* target) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, title, nullptr);
  for (const OptionSpec<Target>& o : specs) PetscCall(o.read(PetscOptionsObject, o.spec, target));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

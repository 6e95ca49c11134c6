// An option declared once, beside the object that owns it (issue 42 item 2, the model
// being contact::ParameterSpec): its name, help, unit, allowed range or values, and the
// field of the owner's options struct it fills, whose initial value is the default. A
// module lists its options (a std::vector<OptionSpec<ItsOptions>>, e.g.
// coupling::PeriodicOptionSpecs()); ReadOptionSpecs reads the list in one
// PetscOptionsBegin block. From the one declaration come:
//   - the reading (PETSc's parsers: what PetscOptionsReal/Int/Bool accept);
//   - the range check and its one-line error "<name> must be in (0, 1), got 2" (or "must be
//     finite, got inf");
//   - -help: "help [unit] (the range, or the values)" with the default;
//   - the value as read, in the text -help shows it ("0.0001", "TRUE", "mmd", a list as typed),
//     kept in an OptionValues for the run record (ReadOptionSpecs's `values`).
// The typo check's names come from the lists gathered in an OptionRegistry (option_registry.hpp).
#pragma once

#include <petscsys.h>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/contact/parameter_spec.hpp"
#include "vibrotherm/options/petsc/option_choice.hpp"
#include "vibrotherm/options/petsc/option_list.hpp"

namespace vibrotherm {

/// Option name → its value as read, in the text -help shows for it: the run record's values.
using OptionValues = std::map<std::string, std::string>;

template <class Target>
struct OptionSpec {
  contact::ParameterSpec spec;  ///< name, help, unit, type, range, choices (the default is the field's value)
  /// Reads spec.name into its field of target (inside PetscOptionsBegin/End) and checks it;
  /// *shown: the value read, as -help shows it.
  std::function<PetscErrorCode(PetscOptionItems*, const contact::ParameterSpec&, Target*, std::string*)> read;
};

/// A value as PETSc's -help shows it: a real by %g, an integer, a flag TRUE or FALSE.
std::string ShownReal(double value);
std::string ShownInt(PetscInt value);
std::string ShownFlag(bool value);

/// A one-line user error unless value is finite ("<name> must be finite, got inf") and lies in
/// spec.range ("<name> <rule> <unit>, got <value>": "-modes_target_frequency must be > 0 Hz, got -5").
PetscErrorCode CheckOptionRange(MPI_Comm comm, const contact::ParameterSpec& spec, double value);

/// A real option [unit] in range.
template <class Target>
OptionSpec<Target> RealOption(const char* name, double Target::*field, contact::Range range, const char* unit,
                              const char* help) {
  return {{name, help, unit, contact::ParameterType::Real, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscCall(PetscOptionsReal(s.name.c_str(), s.describe().c_str(), nullptr, t->*field, &(t->*field), nullptr));
            *shown = ShownReal(t->*field);
            return CheckOptionRange(PetscOptionsObject->comm, s, t->*field);
          }};
}

/// A real option whose default is derived elsewhere (the field's initial value stands for "not
/// given", e.g. -final_time: the source's duration): a value given must lie in range.
template <class Target>
OptionSpec<Target> GivenRealOption(const char* name, double Target::*field, contact::Range range, const char* unit,
                                   const char* help) {
  return {{name, help, unit, contact::ParameterType::Real, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscBool given = PETSC_FALSE;
            PetscCall(PetscOptionsReal(s.name.c_str(), s.describe().c_str(), nullptr, t->*field, &(t->*field), &given));
            *shown = ShownReal(t->*field);
            return given ? CheckOptionRange(PetscOptionsObject->comm, s, t->*field) : PetscErrorCode(0);
          }};
}

/// A list x1,x2,... [unit] of reals, each in range (the field's initial value is the default).
template <class Target>
OptionSpec<Target> RealListOption(const char* name, std::vector<double> Target::*field, contact::Range range,
                                  const char* unit, const char* help) {
  return {{name, help, unit, contact::ParameterType::RealList, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscCall(OptionsRealList(PetscOptionsObject, s.name.c_str(), s.describe().c_str(), &(t->*field), nullptr,
                                      shown));
            for (double value : t->*field) PetscCall(CheckOptionRange(PetscOptionsObject->comm, s, value));
            return PetscErrorCode(0);
          }};
}

/// A text option (a file name, a face name: its owner checks what it names).
template <class Target>
OptionSpec<Target> TextOption(const char* name, std::string Target::*field, const char* help) {
  return {{name, help, "", contact::ParameterType::Text, "", contact::Range::any(), {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            char text[PETSC_MAX_PATH_LEN];
            PetscCall(PetscStrncpy(text, (t->*field).c_str(), sizeof(text)));
            PetscCall(PetscOptionsString(s.name.c_str(), s.help.c_str(), nullptr, text, text, sizeof(text), nullptr));
            t->*field = text;
            *shown = text;
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
          [field](PetscOptionItems* items, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscCall(ReadTextChoice(items, s, field(t)));
            *shown = *field(t);
            return PetscErrorCode(0);
          }};
}

/// An integer option in range.
template <class Target>
OptionSpec<Target> IntOption(const char* name, PetscInt Target::*field, contact::Range range, const char* help) {
  return {{name, help, "", contact::ParameterType::Integer, "", range, {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscCall(PetscOptionsInt(s.name.c_str(), s.describe().c_str(), nullptr, t->*field, &(t->*field), nullptr));
            *shown = ShownInt(t->*field);
            return CheckOptionRange(PetscOptionsObject->comm, s, static_cast<double>(t->*field));
          }};
}

/// An on/off flag ("-name", "-name 0", "-name false").
template <class Target>
OptionSpec<Target> FlagOption(const char* name, bool Target::*field, const char* help) {
  return {{name, help, "", contact::ParameterType::Flag, "", contact::Range::any(), {}},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscBool value = t->*field ? PETSC_TRUE : PETSC_FALSE;
            PetscCall(PetscOptionsBool(s.name.c_str(), s.help.c_str(), nullptr, value, &value, nullptr));
            t->*field = value;
            *shown = ShownFlag(value);
            return PetscErrorCode(0);
          }};
}

/// One of `names`, stored as their index in an enum (or a bool: names {false's, true's}).
template <class Target, class Enum>
OptionSpec<Target> ChoiceOption(const char* name, Enum Target::*field, std::vector<std::string> names,
                                const char* help) {
  return {{name, help, "", contact::ParameterType::Choice, "", contact::Range::any(), names},
          [field](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& s, Target* t, std::string* shown) {
            PetscInt index = static_cast<PetscInt>(t->*field);
            PetscCall(OptionsChoice(PetscOptionsObject, s.name.c_str(), s.help.c_str(), s.choices, &index, nullptr));
            t->*field = static_cast<Enum>(index);
            *shown = s.choices[index];
            return PetscErrorCode(0);
          }};
}

/// An option of a nested struct (Outer::*member) read as part of Outer's list.
template <class Outer, class Inner>
OptionSpec<Outer> NestedOption(Inner Outer::*member, const OptionSpec<Inner>& inner) {
  return {inner.spec, [member, read = inner.read](PetscOptionItems* items, const contact::ParameterSpec& s, Outer* t,
                                                  std::string* shown) { return read(items, s, &(t->*member), shown); }};
}

/// Reads every option of `specs` into target in one options block titled `title`; values (if
/// given): each option's value as read, the first read of an option kept. Collective.
template <class Target>
PetscErrorCode ReadOptionSpecs(MPI_Comm comm, const char* title, const std::vector<OptionSpec<Target>>& specs,
                               Target* target, OptionValues* values = nullptr) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, title, nullptr);
  for (const OptionSpec<Target>& o : specs) {
    std::string shown;
    PetscCall(o.read(PetscOptionsObject, o.spec, target, &shown));
    if (values) values->emplace(o.spec.name, shown);
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm

// Declared parameters: name, help, unit, default and allowed values of one
// user option, bound to a field of the struct it fills.
//
// Plain C++ (no PETSc): the simulator reads the declarations through PETSc's
// options database, vibrotherm-contact through its own argv reader; both parse
// and check values with assign() below, so both accept exactly the same input.
// Defaults are written as a user would type them and go through the same
// parser, so a default can never be a sentinel that a user could also type.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm::contact {

/// Allowed interval of a numeric parameter; numbers must also be finite.
struct Range {
  double lo, hi;
  bool lo_open, hi_open;

  static Range any();                         ///< every finite number
  static Range positive();                    ///< (0, inf)
  static Range at_least(double lo);           ///< [lo, inf)
  static Range between(double lo, double hi);  ///< [lo, hi]
  static Range open(double lo, double hi);     ///< (lo, hi)
  static Range closed_open(double lo, double hi);  ///< [lo, hi)
  static Range open_closed(double lo, double hi);  ///< (lo, hi]
  bool contains(double v) const;
  /// "must be > 0", "must be in (0, 1)", ... (empty for any()).
  std::string rule() const;
};

/// Flag: on/off; RealList: x1,x2,... each in range (both the simulator's options).
enum class ParameterType { Real, Integer, Text, Choice, Flag, RealList };

struct ParameterSpec {
  std::string name;           ///< option with its dash: "-contact_power_C"
  std::string help;
  std::string unit;           ///< "" when dimensionless
  ParameterType type;
  std::string default_value;  ///< as a user types it: "1e18", "biwa", "" (no file)
  Range range;                ///< Real and Integer; RealList: each entry
  std::vector<std::string> choices;  ///< Choice: the allowed values

  /// "help [unit] (range)" for -help listings.
  std::string describe() const;
};

/// A finite number in plain decimal notation ("1e-9", "-0.5", ".5"); InputError
/// "<option>: expected a number, got '<text>'" otherwise (no "1,5", "1e-9x",
/// "nan", "inf", hex, or values beyond the double range).
double parse_real(const std::string& text, const std::string& option);
/// A decimal integer; InputError naming option otherwise.
int parse_integer(const std::string& text, const std::string& option);

/// Checks a numeric value against spec.range; InputError "<name> must be > 0, got -1".
void check_range(const ParameterSpec& spec, double value);
/// Checks a choice; InputError "<name>: unknown value 'x' (known: a|b)".
void check_choice(const ParameterSpec& spec, const std::string& value);

/// A declaration bound to the field of Target that receives the value.
template <class Target>
struct Parameter {
  ParameterSpec spec;
  std::variant<double Target::*, int Target::*, std::string Target::*> field;
};

/// Parses text as the parameter's type, checks it and stores it in target.
template <class Target>
void assign(const Parameter<Target>& p, Target& target, const std::string& text) {
  const ParameterSpec& s = p.spec;
  if (auto* f = std::get_if<double Target::*>(&p.field)) {
    const double v = parse_real(text, s.name);
    check_range(s, v);
    target.*(*f) = v;
  } else if (auto* i = std::get_if<int Target::*>(&p.field)) {
    const int v = parse_integer(text, s.name);
    check_range(s, v);
    target.*(*i) = v;
  } else {
    if (s.type == ParameterType::Choice) check_choice(s, text);
    target.*std::get<std::string Target::*>(p.field) = text;
  }
}

/// Checks the value a field holds (set by code rather than parsed).
template <class Target>
void check_value(const Parameter<Target>& p, const Target& target) {
  if (auto* f = std::get_if<double Target::*>(&p.field)) return check_range(p.spec, target.*(*f));
  if (auto* i = std::get_if<int Target::*>(&p.field)) return check_range(p.spec, target.*(*i));
  if (p.spec.type == ParameterType::Choice) check_choice(p.spec, target.*std::get<std::string Target::*>(p.field));
}

/// Sets every field to its declared default.
template <class Target>
void assign_defaults(const std::vector<Parameter<Target>>& params, Target& target) {
  for (const Parameter<Target>& p : params) assign(p, target, p.spec.default_value);
}

template <class Target>
Parameter<Target> real_parameter(std::string name, double Target::*field, std::string default_value, Range range,
                                 std::string unit, std::string help) {
  return {{name, help, unit, ParameterType::Real, default_value, range, {}}, field};
}

template <class Target>
Parameter<Target> integer_parameter(std::string name, int Target::*field, std::string default_value, Range range,
                                    std::string help) {
  return {{name, help, "", ParameterType::Integer, default_value, range, {}}, field};
}

template <class Target>
Parameter<Target> text_parameter(std::string name, std::string Target::*field, std::string help) {
  return {{name, help, "", ParameterType::Text, "", Range::any(), {}}, field};
}

template <class Target>
Parameter<Target> choice_parameter(std::string name, std::string Target::*field, std::string default_value,
                                   std::vector<std::string> choices, std::string help) {
  return {{name, help, "", ParameterType::Choice, default_value, Range::any(), std::move(choices)}, field};
}

/// A retired option name and the sentence telling what replaced it.
struct RenamedOption {
  const char* old_name;
  const char* replacement;
};

/// "<old> was renamed: use <replacement>".
std::string renamed_message(const RenamedOption& r);

}  // namespace vibrotherm::contact

#include "vibrotherm/contact/parameter_spec.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace vibrotherm::contact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Length of the run of decimal digits starting at text[i].
std::size_t digits_at(const std::string& text, std::size_t i) {
  std::size_t n = 0;
  while (i + n < text.size() && std::isdigit(static_cast<unsigned char>(text[i + n]))) ++n;
  return n;
}

/// [+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?  — nothing else, so that "1,5",
/// "1e-9x", "0x10", "nan" and "inf" are never taken for numbers.
bool plain_decimal(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  const std::size_t whole = digits_at(text, i);
  i += whole;
  std::size_t fraction = 0;
  if (i < text.size() && text[i] == '.') {
    fraction = digits_at(text, i + 1);
    i += 1 + fraction;
  }
  if (whole + fraction == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    const std::size_t exponent = digits_at(text, i);
    if (exponent == 0) return false;
    i += exponent;
  }
  return i == text.size();
}

}  // namespace

Range Range::any() { return {-kInf, kInf, true, true}; }
Range Range::positive() { return {0.0, kInf, true, true}; }
Range Range::at_least(double lo) { return {lo, kInf, false, true}; }
Range Range::between(double lo, double hi) { return {lo, hi, false, false}; }
Range Range::open(double lo, double hi) { return {lo, hi, true, true}; }
Range Range::closed_open(double lo, double hi) { return {lo, hi, false, true}; }
Range Range::open_closed(double lo, double hi) { return {lo, hi, true, false}; }

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::rule() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (!has_lo && !has_hi) return "must be finite";
  if (!has_hi) return std::string("must be ") + (lo_open ? "> " : ">= ") + number_text(lo);
  if (!has_lo) return std::string("must be ") + (hi_open ? "< " : "<= ") + number_text(hi);
  return std::string("must be in ") + (lo_open ? "(" : "[") + number_text(lo) + ", " + number_text(hi) +
         (hi_open ? ")" : "]");
}

std::string ParameterSpec::describe() const {
  std::string text = help;
  if (!unit.empty()) text += " [" + unit + "]";
  if (type == ParameterType::Real || type == ParameterType::Integer) {
    if (std::isfinite(range.lo) || std::isfinite(range.hi)) text += " (" + range.rule() + ")";
  } else if (type == ParameterType::RealList) {
    if (std::isfinite(range.lo) || std::isfinite(range.hi)) text += " (each " + range.rule().substr(8) + ")";  // "must be >= 0" -> "each >= 0"
  } else if (type == ParameterType::Choice) {
    std::string known;
    for (const std::string& c : choices) known += (known.empty() ? "" : "|") + c;
    text += " (" + known + ")";
  }
  return text;
}

double parse_real(const std::string& text, const std::string& option) {
  const auto bad = [&](const char* why) { return InputError(option + ": " + why + ", got '" + text + "'"); };
  if (text.empty()) throw InputError(option + ": expected a number, got nothing");
  if (!plain_decimal(text)) throw bad("expected a number");
  const std::size_t start = text[0] == '+' ? 1 : 0;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data() + start, text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range || !std::isfinite(value)) throw bad("number out of the double range");
  if (ec != std::errc() || end != text.data() + text.size()) throw bad("expected a number");
  return value;
}

int parse_integer(const std::string& text, const std::string& option) {
  if (text.empty()) throw InputError(option + ": expected an integer, got nothing");
  const std::size_t start = text[0] == '+' ? 1 : 0;
  if (digits_at(text, text[0] == '+' || text[0] == '-' ? 1 : 0) + (text[0] == '+' || text[0] == '-') != text.size())
    throw InputError(option + ": expected an integer, got '" + text + "'");
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data() + start, text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) throw InputError(option + ": integer out of range, got '" + text + "'");
  if (ec != std::errc() || end != text.data() + text.size() || start == text.size())
    throw InputError(option + ": expected an integer, got '" + text + "'");
  return value;
}

void check_range(const ParameterSpec& spec, double value) {
  if (spec.range.contains(value)) return;
  throw InputError(spec.name + " " + spec.range.rule() + ", got " + number_text(value));
}

void check_choice(const ParameterSpec& spec, const std::string& value) {
  std::string known;
  for (const std::string& c : spec.choices) {
    if (c == value) return;
    known += (known.empty() ? "" : "|") + c;
  }
  throw InputError(spec.name + ": unknown value '" + value + "' (known: " + known + ")");
}

std::string renamed_message(const RenamedOption& r) {
  return std::string(r.old_name) + " was renamed: use " + r.replacement;
}

}  // namespace vibrotherm::contact

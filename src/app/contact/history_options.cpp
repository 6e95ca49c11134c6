#include "history_options.hpp"

namespace vibrotherm::app {
namespace {

using H = HistoryOptions;
using contact::Range;

/// The sinusoid of one displacement (a, b or b2).
struct SineFields {
  const char *x, *what, *default_amplitude, *default_offset;
  double H::*amplitude;
  double H::*offset;
  double H::*phase;
  double H::*rate;
};

/// -history_<x>_amplitude, _offset, _phase, _rate.
void append_sine(std::vector<contact::Parameter<H>>& list, const SineFields& f) {
  struct Field {
    const char *suffix, *unit, *help, *default_value;
    double H::*field;
  };
  const Field fields[] = {{"amplitude", "m", "amplitude", f.default_amplitude, f.amplitude},
                          {"offset", "m", "offset", f.default_offset, f.offset},
                          {"phase", "deg", "phase", "0", f.phase},
                          {"rate", "m/s", "drift rate", "0", f.rate}};
  const std::string prefix = std::string("-history_") + f.x + "_", what = std::string("built-in history: ") + f.what;
  for (const Field& g : fields)
    list.push_back(contact::real_parameter(prefix + g.suffix, g.field, g.default_value, Range::any(), g.unit,
                                           what + " " + g.help));
}

std::vector<contact::Parameter<H>> make_history_parameters() {
  std::vector<contact::Parameter<H>> list = {
      contact::text_parameter("-history", &H::file,
                              "CSV file with columns t,a,b (t [s], a, b [m]), or t,a,b,b2 (header line needed) for two "
                              "tangential components; without it, the built-in sinusoids"),
      contact::text_parameter("-cell_history", &H::cell_file, "the same as -history"),
      contact::text_parameter("-o", &H::output, "output CSV file (default: standard output)"),
  };
  append_sine(list, {"a", "normal half approach a", "0", "1e-8", &H::a_amplitude, &H::a_offset, &H::a_phase,
                     &H::a_rate});
  append_sine(list, {"b", "tangential half displacement b", "5e-9", "0", &H::b_amplitude, &H::b_offset,
                     &H::b_phase, &H::b_rate});
  append_sine(list, {"b2", "second tangential half displacement b2 (two components unless zero)", "0", "0",
                     &H::b2_amplitude, &H::b2_offset, &H::b2_phase, &H::b2_rate});
  list.push_back(contact::real_parameter("-history_frequency", &H::frequency, "1e5", Range::positive(), "Hz",
                                         "built-in history: frequency"));
  list.push_back(contact::real_parameter("-history_cycles", &H::cycles, "2", Range::positive(), "",
                                         "built-in history: number of cycles"));
  list.push_back(contact::integer_parameter("-history_steps_per_cycle", &H::steps_per_cycle, "100",
                                            Range::between(4, 1e8), "built-in history: steps per cycle"));
  list.push_back(contact::real_parameter("-history_ramp_cycles", &H::ramp_cycles, "0", Range::at_least(0.0), "",
                                         "built-in history: the amplitudes grow linearly over this many cycles"));
  return list;
}

}  // namespace

const std::vector<contact::Parameter<HistoryOptions>>& history_parameters() {
  static const std::vector<contact::Parameter<HistoryOptions>> list = make_history_parameters();
  return list;
}

HistoryOptions::HistoryOptions() { contact::assign_defaults(history_parameters(), *this); }

contact::SineHistory HistoryOptions::sine() const {
  contact::SineHistory h;
  h.a = {a_amplitude, a_offset, a_phase, a_rate};
  h.b = {b_amplitude, b_offset, b_phase, b_rate};
  h.b2 = {b2_amplitude, b2_offset, b2_phase, b2_rate};
  h.frequency = frequency;
  h.cycles = cycles;
  h.steps_per_cycle = steps_per_cycle;
  h.ramp_cycles = ramp_cycles;
  return h;
}

std::string HistoryOptions::history_file() const {
  if (!file.empty() && !cell_file.empty()) throw contact::InputError("-history and -cell_history: give one of them");
  return file.empty() ? cell_file : file;
}

}  // namespace vibrotherm::app

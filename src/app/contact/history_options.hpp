// The options of vibrotherm-contact besides the contact laws': where the
// (t, a, b) history comes from and where the rows go.
#pragma once

#include <string>
#include <vector>

#include "vibrotherm/contact/cell_history.hpp"
#include "vibrotherm/contact/parameter_spec.hpp"

namespace vibrotherm::app {

struct HistoryOptions {
  HistoryOptions();  ///< every field at its declared default

  std::string file, cell_file;  ///< -history, -cell_history (the same option)
  std::string output;           ///< -o ("": standard output)
  /// -history_{a,b,b2}_{amplitude,offset,phase,rate}: the sinusoids of a, b and
  /// the second tangential component b2 (zero: one component).
  double a_amplitude, a_offset, a_phase, a_rate;
  double b_amplitude, b_offset, b_phase, b_rate;
  double b2_amplitude, b2_offset, b2_phase, b2_rate;
  double frequency, cycles, ramp_cycles;
  int steps_per_cycle;

  /// The built-in sinusoids.
  contact::SineHistory sine() const;
  /// The CSV file given with -history or -cell_history ("" for none);
  /// InputError if both are given.
  std::string history_file() const;
  /// The option that gave history_file(): -history or -cell_history.
  std::string history_option() const { return file.empty() && !cell_file.empty() ? "-cell_history" : "-history"; }
};

const std::vector<contact::Parameter<HistoryOptions>>& history_parameters();

}  // namespace vibrotherm::app

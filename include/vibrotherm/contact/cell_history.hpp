// Prescribed (t, a, b) histories for driving one contact cell: read from CSV or
// built from sinusoids and ramps. b has one tangential component, or two when
// the history gives a second one (b2). Used by vibrotherm-contact (law
// calibration) and the tests.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {

struct HistoryPoint {
  double t, a;
  Tangential b;
};

/// Reads a CSV with columns t,a,b, or t,a,b,b2 when the header line says so (a
/// header line and # comments allowed). InputError naming option, the file and
/// line on bad rows or non-increasing t.
std::vector<HistoryPoint> read_history_csv(const std::string& path, const std::string& option = "-history");

/// x(t) = offset + rate t + ramp(t) · amplitude · sin(2π f t + phase).
struct SineComponent {
  double amplitude = 0.0, offset = 0.0, phase_deg = 0.0, rate = 0.0;
};

struct SineHistory {
  SineComponent a, b;
  SineComponent b2;             ///< the second tangential component, driven unless zero
  /// True when b2 is not identically zero: the history then has two tangential components.
  bool has_second_tangential() const { return b2.amplitude != 0.0 || b2.offset != 0.0 || b2.rate != 0.0; }
  double frequency = 1e5;       ///< [Hz]
  double cycles = 2.0;
  int steps_per_cycle = 100;
  double ramp_cycles = 0.0;     ///< amplitudes grow linearly over this many cycles
};

/// The most steps make_sine_history() generates.
constexpr long kMaxHistorySteps = 100000000;

/// Samples the history at steps_per_cycle points per cycle (t = 0 included).
std::vector<HistoryPoint> make_sine_history(const SineHistory& h);

/// Drives cell 0 of law (initialised at the first point, a + a0) through the
/// history and writes t,a,b,b0,btilde,N,T,state,dW,W rows; with two tangential
/// components t,a,b,b2,b0,b02,btilde,btilde2,N,T,T2,state,dW,W. Returns Σ dW.
/// InputError as soon as a row would hold a non-finite number (the rows
/// written so far must then be discarded).
double drive_cell(CrackLaw& law, const std::vector<HistoryPoint>& history, double a0, std::ostream& out);

}  // namespace vibrotherm::contact

#include "vibrotherm/contact/cell_history.hpp"

#include "vibrotherm/contact/csv_rows.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

namespace vibrotherm::contact {

std::vector<HistoryPoint> read_history_csv(const std::string& path, const std::string& option) {
  std::vector<HistoryPoint> rows;
  for (const CsvRow& r : read_csv_rows(path, option, {"t", "a", "b"})) {
    const HistoryPoint p{r.values[0], r.values[1], r.values[2]};
    if (!rows.empty() && !(p.t > rows.back().t))
      throw InputError(option + " " + path + " line " + std::to_string(r.line) + ": t must increase");
    rows.push_back(p);
  }
  if (rows.size() < 2) throw InputError(option + " " + path + ": needs at least two rows");
  return rows;
}

std::vector<HistoryPoint> make_sine_history(const SineHistory& h) {
  if (!(h.frequency > 0.0)) throw InputError("-history_frequency must be > 0");
  if (!(h.cycles > 0.0)) throw InputError("-history_cycles must be > 0");
  if (h.steps_per_cycle < 4) throw InputError("-history_steps_per_cycle must be >= 4");
  if (h.ramp_cycles < 0.0) throw InputError("-history_ramp_cycles must be >= 0");
  // A bound on the rows keeps the product finite and the output file sane.
  if (!(h.cycles * h.steps_per_cycle <= kMaxHistorySteps))
    throw InputError("-history_cycles x -history_steps_per_cycle must be <= " + std::to_string(kMaxHistorySteps) +
                     " steps");
  const long steps = std::lround(h.cycles * h.steps_per_cycle);
  std::vector<HistoryPoint> rows;
  rows.reserve(steps + 1);
  for (long k = 0; k <= steps; ++k) {
    const double cycle = double(k) / h.steps_per_cycle, t = cycle / h.frequency;
    const double ramp = h.ramp_cycles > 0.0 ? std::min(1.0, cycle / h.ramp_cycles) : 1.0;
    auto value = [&](const SineComponent& c) {
      return c.offset + c.rate * t + ramp * c.amplitude * std::sin(2.0 * M_PI * cycle + c.phase_deg * M_PI / 180.0);
    };
    rows.push_back({t, value(h.a), value(h.b)});
  }
  return rows;
}

namespace {

/// InputError when a row holds a non-finite number: the history drove the law
/// beyond the double range (e.g. amplitudes of 1e200 m), nothing to report.
void check_finite_row(std::size_t k, const HistoryPoint& p, double a, double b0, const StepResult& r, double W) {
  const double values[] = {p.t, a, p.b, b0, p.b - b0, r.N, r.T, r.dW, W};
  const char* names[] = {"t", "a", "b", "b0", "btilde", "N", "T", "dW", "W"};
  for (int i = 0; i < 9; ++i) {
    if (std::isfinite(values[i])) continue;
    std::ostringstream msg;
    msg << "history row " << k + 1 << " (t = " << p.t << "): " << names[i] << " = " << values[i]
        << " is not finite; the history's values are out of range for this law";
    throw InputError(msg.str());
  }
}

}  // namespace

double drive_cell(CrackLaw& law, const std::vector<HistoryPoint>& history, double a0, std::ostream& out) {
  out << "t,a,b,b0,btilde,N,T,state,dW,W\n";
  const double a_first = history.front().a + a0, b_first = history.front().b;
  law.initialize(1, &a_first, &b_first);
  double W = 0.0;
  for (std::size_t k = 0; k < history.size(); ++k) {
    const double a = history[k].a + a0, b = history[k].b;
    StepResult r;
    if (k == 0) {
      const Traction t = law.trial(0, a, b);
      r = {t.N, t.T, 0.0, a > 0.0 ? ContactState::Stick : ContactState::Loss};
    } else {
      r = law.commit(0, a, b);
    }
    W += r.dW;
    const double b0 = law.slip_offset(0);
    check_finite_row(k, history[k], a, b0, r, W);
    out << history[k].t << ',' << a << ',' << b << ',' << b0 << ',' << b - b0 << ',' << r.N << ',' << r.T << ','
        << to_string(r.state) << ',' << r.dW << ',' << W << '\n';
  }
  return W;
}

}  // namespace vibrotherm::contact

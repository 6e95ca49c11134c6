#include "vibrotherm/contact/cell_history.hpp"

#include "vibrotherm/contact/csv_rows.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

namespace vibrotherm::contact {

std::vector<HistoryPoint> read_history_csv(const std::string& path, const std::string& option) {
  std::vector<HistoryPoint> rows;
  for (const CsvRow& r : read_csv_rows(path, option, {"t", "a", "b"}, {"b2"})) {
    const std::vector<double>& v = r.values;
    const HistoryPoint p{v[0], v[1], v.size() == 4 ? Tangential(v[2], v[3]) : Tangential(v[2])};
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
    const Tangential b = h.has_second_tangential() ? Tangential(value(h.b), value(h.b2)) : Tangential(value(h.b));
    rows.push_back({t, value(h.a), b});
  }
  return rows;
}

namespace {

/// The numbers of one output row, in the order of its columns but the state.
struct CellRow {
  std::vector<const char*> names;
  std::vector<double> values;
  void add(const char* name, double value) {
    names.push_back(name);
    values.push_back(value);
  }
  /// A tangential quantity: `name` for the first component, `second` for the second.
  void add(const char* name, const char* second, const Tangential& value) {
    add(name, value[0]);
    if (value.components() == 2) add(second, value[1]);
  }
};

/// t,a,b[,b2],b0[,b02],btilde[,btilde2],N,T[,T2] of a row, then dW,W.
CellRow cell_row(double t, double a, const Tangential& b, const Tangential& b0, const StepResult& r, double W) {
  Tangential btilde = b;
  for (int k = 0; k < b.components(); ++k) btilde[k] = b[k] - b0[k];
  CellRow row;
  row.add("t", t);
  row.add("a", a);
  row.add("b", "b2", b);
  row.add("b0", "b02", b0);
  row.add("btilde", "btilde2", btilde);
  row.add("N", r.N);
  row.add("T", "T2", r.T);
  row.add("dW", r.dW);
  row.add("W", W);
  return row;
}

/// InputError when a row holds a non-finite number: the history drove the law
/// beyond the double range (e.g. amplitudes of 1e200 m), nothing to report.
void check_finite_row(std::size_t k, const CellRow& row) {
  for (std::size_t i = 0; i < row.values.size(); ++i) {
    if (std::isfinite(row.values[i])) continue;
    std::ostringstream msg;
    msg << "history row " << k + 1 << " (t = " << row.values[0] << "): " << row.names[i] << " = " << row.values[i]
        << " is not finite; the history's values are out of range for this law";
    throw InputError(msg.str());
  }
}

/// One line of the output: items (the column names or the numbers) comma
/// separated, with `state` between the tractions and dW (the last two items).
template <class Item>
void write_line(const std::vector<Item>& items, const char* state, std::ostream& out) {
  const std::size_t before_state = items.size() - 2;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i == before_state) out << state << ',';
    out << items[i] << (i + 1 < items.size() ? ',' : '\n');
  }
}

}  // namespace

double drive_cell(CrackLaw& law, const std::vector<HistoryPoint>& history, double a0, std::ostream& out) {
  const double a_first = history.front().a + a0;
  const Tangential b_first = history.front().b;
  law.initialize(1, &a_first, &b_first);
  double W = 0.0;
  for (std::size_t k = 0; k < history.size(); ++k) {
    const double a = history[k].a + a0;
    const Tangential& b = history[k].b;
    StepResult r;
    if (k == 0) {
      const Traction t = law.trial(0, a, b);
      r = {t.N, t.T, 0.0, a > 0.0 ? ContactState::Stick : ContactState::Loss};
    } else {
      r = law.commit(0, a, b);
    }
    W += r.dW;
    const CellRow row = cell_row(history[k].t, a, b, law.slip_offset(0), r, W);
    check_finite_row(k, row);
    if (k == 0) write_line(row.names, "state", out);
    write_line(row.values, to_string(r.state), out);
  }
  return W;
}

}  // namespace vibrotherm::contact

// Tabulated normal law from a CSV of (a, N) pairs.
//
// The interpolant must keep what the memory diagram relies on: N increasing,
// N' continuous and non-decreasing (a convex law: the spring-bed density N'' is
// non-negative). A cubic PCHIP is monotone but not convex in general, so we use
// a shape-preserving C¹ quadratic spline (Schumaker 1983): per data interval two
// parabolas joined at an inner knot chosen so that the slope stays between the
// node slopes. M = ∫N is then a piecewise cubic, exact.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "vibrotherm/contact/csv_rows.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

/// One parabola N = y0 + d0 x + c x², x = a − x0, valid on [x0, next x0).
struct Piece {
  double x0, y0, d0, c, M0;
};

class TableLaw final : public NormalLaw {
 public:
  explicit TableLaw(std::vector<Piece> pieces) : pieces_(std::move(pieces)) {}

  NormalLawValue eval(double a) const override {
    if (!(a > 0.0)) return {};
    auto it = std::upper_bound(pieces_.begin(), pieces_.end(), a,
                               [](double v, const Piece& p) { return v < p.x0; });
    const Piece& p = *(it - 1);
    const double x = a - p.x0;
    return {p.y0 + x * (p.d0 + x * p.c), p.d0 + 2.0 * p.c * x,
            p.M0 + x * (p.y0 + x * (0.5 * p.d0 + x * p.c / 3.0))};
  }
  double stiffness_at_zero() const override { return pieces_.front().d0; }
  /// Exact: N'' = 2c is constant on each parabola, so each piece adds 2c ∫ (α − x)^k dα.
  DensityMoments density_moments(double x, const NormalLawValue&, double y, const NormalLawValue&) const override {
    DensityMoments m;
    auto it = std::upper_bound(pieces_.begin(), pieces_.end(), x, [](double v, const Piece& p) { return v < p.x0; });
    for (it = it == pieces_.begin() ? it : it - 1; it != pieces_.end() && it->x0 < y; ++it) {
      const double lo = std::max(it->x0, x) - x;
      const double hi = (it + 1 == pieces_.end() ? y : std::min((it + 1)->x0, y)) - x;
      if (!(hi > lo)) continue;
      const double w = 2.0 * it->c * (hi - lo);
      m.m0 += w;
      m.m1 += w * 0.5 * (hi + lo);
      m.m2 += w * (hi * hi + hi * lo + lo * lo) / 3.0;
    }
    return m;
  }
  std::string name() const override { return "table"; }

 private:
  std::vector<Piece> pieces_;
};

struct Row {
  double a, N;
  int line;
};

std::vector<Row> read_rows(const std::string& file) {
  const std::string opt = "-contact_table_file " + file;
  std::vector<Row> rows;
  for (const CsvRow& r : read_csv_rows(file, "-contact_table_file", {"a", "N"})) {
    if (r.values[1] < 0.0) throw InputError(opt + " line " + std::to_string(r.line) + ": N must be >= 0");
    rows.push_back({r.values[0], r.values[1], r.line});
  }
  if (rows.empty()) throw InputError(opt + ": no data rows");
  if (rows.front().a > 0.0) rows.insert(rows.begin(), Row{0.0, 0.0, rows.front().line});
  if (rows.front().a < 0.0 || rows.front().N != 0.0)
    throw InputError(opt + " line " + std::to_string(rows.front().line) +
                     ": the table must start at a >= 0 with N(0) = 0");
  if (rows.size() < 2) throw InputError(opt + ": needs at least one row with a > 0");
  return rows;
}

/// Schumaker's two parabolas on one interval with end slopes d0 <= δ <= d1.
void append_interval(std::vector<Piece>& pieces, double& M, const Row& p, const Row& q, double d0,
                     double d1) {
  const double h = q.a - p.a, delta = (q.N - p.N) / h;
  double lambda = 0.5;
  if (d1 - d0 > 1e-14 * std::max(std::abs(d0), std::abs(d1))) {
    const double lo = std::max(0.0, (d1 + d0 - 2.0 * delta) / (d1 - d0));
    const double hi = std::min(1.0, 2.0 * (d1 - delta) / (d1 - d0));
    lambda = 0.5 * (lo + hi);
  }
  const double dbar = 2.0 * delta - lambda * d0 - (1.0 - lambda) * d1;
  const double h1 = lambda * h, h2 = h - h1;
  if (h1 > 0.0) {
    const double c = (dbar - d0) / (2.0 * h1);
    pieces.push_back({p.a, p.N, d0, c, M});
    M += h1 * (p.N + h1 * (0.5 * d0 + h1 * c / 3.0));
  }
  if (h2 > 0.0) {
    const double y = p.N + 0.5 * (d0 + dbar) * h1;
    const double c = (d1 - dbar) / (2.0 * h2);
    pieces.push_back({p.a + h1, y, dbar, c, M});
    M += h2 * (y + h2 * (0.5 * dbar + h2 * c / 3.0));
  }
}

}  // namespace

const ContactParameterList& table_law_parameters() {
  static const ContactParameterList list = {
      text_parameter("-contact_table_file", &ContactParameters::table_file,
                     "table law: CSV file with columns a,N (a [m], N [Pa])"),
  };
  return list;
}

std::unique_ptr<NormalLaw> create_table_law(const ContactParameters& params) {
  if (params.table_file.empty()) throw InputError("-contact_table_file: a file is required for the table law");
  const std::vector<Row> rows = read_rows(params.table_file);
  const std::string opt = "-contact_table_file " + params.table_file;
  const std::size_t n = rows.size() - 1;  // intervals
  std::vector<double> delta(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double h = rows[i + 1].a - rows[i].a;
    if (!(h > 0.0)) throw InputError(opt + " line " + std::to_string(rows[i + 1].line) + ": a must increase");
    delta[i] = (rows[i + 1].N - rows[i].N) / h;
    if (delta[i] < 0.0)
      throw InputError(opt + " line " + std::to_string(rows[i + 1].line) + ": N decreases (law must be monotone)");
    if (i > 0 && delta[i] < delta[i - 1] * (1.0 - 1e-12))
      throw InputError(opt + " line " + std::to_string(rows[i + 1].line) +
                       ": slope decreases (law must be convex)");
  }
  // Node slopes: derivative of the parabola through three neighbours (exact for
  // quadratic data), always between the adjacent secants for convex data.
  std::vector<double> d(n + 1);
  if (n == 1) {
    d[0] = d[1] = delta[0];
  } else {
    for (std::size_t i = 1; i < n; ++i) {
      const double h0 = rows[i].a - rows[i - 1].a, h1 = rows[i + 1].a - rows[i].a;
      d[i] = (h1 * delta[i - 1] + h0 * delta[i]) / (h0 + h1);
    }
    const double h0 = rows[1].a - rows[0].a, h1 = rows[2].a - rows[1].a;
    d[0] = std::clamp(delta[0] - h0 * (delta[1] - delta[0]) / (h0 + h1), 0.0, delta[0]);
    const double g0 = rows[n - 1].a - rows[n - 2].a, g1 = rows[n].a - rows[n - 1].a;
    d[n] = std::max(delta[n - 1], delta[n - 1] + g1 * (delta[n - 1] - delta[n - 2]) / (g0 + g1));
  }
  std::vector<Piece> pieces;
  double M = 0.0;
  for (std::size_t i = 0; i < n; ++i) append_interval(pieces, M, rows[i], rows[i + 1], d[i], d[i + 1]);
  // Beyond the table: continue with the last slope (linear, still convex).
  pieces.push_back({rows[n].a, rows[n].N, d[n], 0.0, M});
  return std::make_unique<TableLaw>(std::move(pieces));
}

}  // namespace vibrotherm::contact

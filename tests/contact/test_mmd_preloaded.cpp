// Requirement (issue 23): a pre-loaded contact that barely moves dissipates what
// its springs can physically dissipate, at every scale of motion. Generated
// histories: pre-loads 1e-9–1e-7 m, tangential amplitudes 1e-18 m to 1e-2·a,
// normal wiggles of 1e-16–1e-10 relative, reversals at every scale. Checked
// against references that share nothing with the MMD's closed forms:
//  - per step, ΔW >= 0 and ΔW <= the work of the springs within reach of the
//    moving wedge edges (each slips at most r − d, under at most μ(a_max − α)dN'),
//    integrated by quadrature in local coordinates from the diagram before the step;
//  - per steady cycle at constant a, Mindlin's energy (its series in u/a, which
//    keeps every digit where the closed form would cancel);
//  - with normal wiggles, a bed of discrete Jenkins springs resolving the slip zone,
//    positioned relative to the pre-load so that it sees the same rounded path.
#include <gtest/gtest.h>

#include <random>

#include "contact_test_support.hpp"
#include "vibrotherm/contact/memory_diagram.hpp"

namespace vibrotherm::contact {
namespace {

/// Biwa's default law, N = K a² with K = (2(1 − m)C_B)^(1/(1−m)) = 1e22 Pa/m²: N'' = 2K.
struct Preloaded {
  ContactParameters p;
  std::unique_ptr<NormalLaw> law;
  MmdConfig cfg;
  double K, tm;
  explicit Preloaded(double mu = 1.0) {
    p.mu = mu;
    p.nu = 0.33;
    law = create_normal_law(p);
    cfg = MmdConfig{p.mu, p.theta(), p.mmd_rel_tol, static_cast<std::size_t>(p.mmd_max_breakpoints)};
    K = std::pow(2.0 * (1.0 - p.biwa_m) * p.biwa_C, 1.0 / (1.0 - p.biwa_m));
    tm = p.theta() * p.mu;
  }
  double ddN() const { return 2.0 * K; }
};

/// ∫ (r − d(α))⁺ (a_max − α) N'' dα over one diagram segment [x, y] where the
/// distance to a wedge edge is d(x) + s (α − x): exact (N'' is constant, the
/// integrand quadratic), evaluated in u = α − x so that a sliver of width 1e-16·a
/// keeps its digits.
double reach_work(double x, double y, double d_x, double slope, double r, double a_max, double ddN) {
  double lo = 0.0, hi = y - x;  // where r − d > 0
  if (slope > 0.0) hi = std::min(hi, (r - d_x) / slope);
  else if (slope < 0.0) lo = std::max(lo, (r - d_x) / slope);
  else if (!(r > d_x)) return 0.0;
  if (!(hi > lo)) return 0.0;
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * g[i];
    sum += w[i] * std::max(0.0, r - d_x - slope * u) * ((a_max - x) - u);
  }
  return 0.5 * (hi - lo) * sum * ddN;
}

/// The most a step from the committed diagram to (a2, bt2) can dissipate, and the
/// relative rounding the MMD may add to it: its slip zone of width ~r/θμ ends on
/// abscissae near a, resolved to ulp(a), and W grows as the zone's cube.
struct Bound {
  double work = 0.0, rounding = 0.0;
};
Bound physical_bound(const Preloaded& c, const MemoryDiagram& cell, double a2, double b2) {
  const auto& pts = cell.diagram();
  if (pts.empty()) return {};
  const double a1 = cell.a(), bt1 = pts.back().f, bt2 = b2 - cell.b0();
  const double da = a2 - a1, db = bt2 - bt1, a_max = std::max(a1, a2);
  const double r_lo = db - c.tm * da, r_up = -db - c.tm * da;
  double work = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double x = pts[k].alpha, y = pts[k + 1].alpha, fx = pts[k].f;
    const double slope_f = (pts[k + 1].f - fx) / (y - x);
    // d_lo = f − (b̃1 − θμ(a1 − α)), d_up = (b̃1 + θμ(a1 − α)) − f.
    const double dlo = (fx - bt1) + c.tm * (a1 - x), dup = (bt1 - fx) + c.tm * (a1 - x);
    if (r_lo > 0.0) work += reach_work(x, y, dlo, slope_f - c.tm, r_lo, a_max, c.ddN());
    if (r_up > 0.0) work += reach_work(x, y, dup, -slope_f - c.tm, r_up, a_max, c.ddN());
  }
  // Springs born in the step start on the pushing edge: slip <= r, force <= μ(a2 − α).
  const double r = std::max({r_lo, r_up, 0.0});
  if (da > 0.0) work += r * c.ddN() * 0.5 * da * da;
  const double zone = std::max(r / c.tm, std::abs(da));
  return {2.0 * c.p.mu * work, 1e-7 + 16.0 * std::numeric_limits<double>::epsilon() * a_max / zone};
}

/// Mindlin's energy per steady cycle ±b* at constant a, N = K a^p:
/// W = 8θμ² K a^(p+1) F(u/a), F(x) = Σ_k (−1)^(k−1) C(p, k−1) (k − 2)/k x^k (from k = 3).
double mindlin_cycle(const Preloaded& c, double a, double b_star) {
  const double p = 2.0, x = b_star / c.tm / a;  // Biwa m = 1/2: p = 2, F = x³/3 exactly
  double F = 0.0, binom = p * (p - 1.0) / 2.0, power = x * x * x, sign = 1.0;  // C(p, k − 1), x^k at k = 3
  for (int k = 3; k < 40 && binom != 0.0; ++k) {
    F += sign * binom * (k - 2.0) / k * power;
    binom *= (p - (k - 1.0)) / k;
    power *= x;
    sign = -sign;
  }
  return 8.0 * c.p.theta() * c.p.mu * c.p.mu * c.K * std::pow(a, p + 1.0) * F;
}

/// Triangle wave of period 1 and amplitude 1, exact at its extremes (t = 1/4, 3/4).
double triangle(double t) {
  const double s = t - std::floor(t);
  return s < 0.25 ? 4.0 * s : (s < 0.75 ? 2.0 - 4.0 * s : 4.0 * s - 4.0);
}

/// One generated history: pre-load, tangential scales with reversals at every scale, normal wiggles.
struct History {
  double a0, b_star, wiggle;
  double a(double t) const { return a0 * (1.0 + wiggle * std::sin(2 * M_PI * 3.1 * t + 0.3)); }
  double b(double t) const {
    return b_star * (triangle(t) + 1e-3 * triangle(17.0 * t + 0.1) + 1e-7 * triangle(331.0 * t + 0.2));
  }
};

TEST(MmdPreloaded, EveryStepWithinWhatItsSpringsCanDissipate) {
  const Preloaded c;
  std::mt19937_64 rng(2023);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, U(rng)); };
  double worst_ratio = 0.0;
  for (int trial = 0; trial < 60; ++trial) {
    History h;
    h.a0 = log_uniform(1e-9, 1e-7);
    h.b_star = log_uniform(1e-18, 1e-2 * h.a0);
    h.wiggle = trial % 4 == 0 ? 0.0 : log_uniform(1e-16, 1e-10);
    MemoryDiagram cell;
    cell.reset(*c.law, h.a0, 0.0);
    const int steps = 3000;
    for (int k = 1; k <= steps; ++k) {
      const double t = 2.0 * k / steps, a = h.a(t), b = h.b(t);
      const Bound bound = physical_bound(c, cell, a, b);
      const StepResult r = cell.commit(*c.law, c.cfg, a, b);
      ASSERT_GE(r.dW, 0.0);
      // The bound is the exact dissipation when one edge pushes at constant a: allow the MMD's rounding.
      ASSERT_LE(r.dW, bound.work * (1.0 + bound.rounding) + 1e-300)
          << "trial " << trial << " step " << k << ": a0 " << h.a0 << " b* " << h.b_star << " wiggle " << h.wiggle;
      if (bound.work > 0.0) worst_ratio = std::max(worst_ratio, r.dW / bound.work);
    }
  }
  RecordProperty("largest_dW_over_bound", std::to_string(worst_ratio));
}

TEST(MmdPreloaded, MindlinCycleEnergyAtEveryScale) {
  const Preloaded c;
  for (double a0 : {1e-9, 1e-8, 1e-7}) {
    for (double b_star = 1e-18; b_star <= 1e-2 * a0; b_star *= 10.0) {
      MemoryDiagram cell;
      cell.reset(*c.law, a0, 0.0);
      const int n = 400;  // steps per cycle; extremes hit exactly (triangle)
      double W3 = 0.0;
      for (int k = 1; k <= 3 * n; ++k) {
        const StepResult r = cell.commit(*c.law, c.cfg, a0, b_star * triangle(double(k) / n));
        if (k > 2 * n) W3 += r.dW;
      }
      const double ref = mindlin_cycle(c, a0, b_star);
      // The slip zone u = b*/θμ ends on abscissae near a0, resolved to ulp(a0): W ∝ u³ keeps ~u/ulp digits.
      const double tol = 1e-8 + 256.0 * std::numeric_limits<double>::epsilon() * a0 / (b_star / c.tm);
      EXPECT_NEAR(W3, ref, tol * ref) << "a0 " << a0 << " b* " << b_star;
    }
  }
}

// Steps far smaller than the slip zone still follow Cattaneo–Mindlin's virgin branch
// T = μ[N(a) − N(a − b/θμ)] ≈ N'(a) b/θ: a diagram tolerance above the step size once
// tilted the last segment instead, giving N(a) b/(θa), half the stiffness for Biwa's law.
TEST(MmdPreloaded, TinyStepsKeepTheTangentialStiffness) {
  const Preloaded c;
  for (double a0 : {1e-9, 2e-8, 1e-7}) {
    MemoryDiagram cell;
    cell.reset(*c.law, a0, 0.0);
    const double b_end = 1e-7 * a0;  // 100 steps of 1e-9 a0
    StepResult r;
    for (int k = 1; k <= 100; ++k) r = cell.commit(*c.law, c.cfg, a0, b_end * k / 100);
    const double u = b_end / c.tm, ref = c.p.mu * c.K * u * (2.0 * a0 - u);  // N = K a²
    EXPECT_NEAR(r.T[0], ref, 1e-6 * ref) << "a0 " << a0;
  }
}

/// Jenkins springs at offsets δ_i from the pre-load a0 with weights N''·h, over a band
/// [δ_lo, δ_hi] that holds every spring that can slip; springs deeper than the band
/// stay stuck (no work). Spring i touches while a − a0 > δ_i.
class LocalSpringBed {
 public:
  LocalSpringBed(const Preloaded& c, double a0, double lo, double hi, int count) : c_(c), a0_(a0) {
    const double h = (hi - lo) / count;
    for (int i = 0; i < count; ++i) delta_.push_back(lo + (i + 0.5) * h);
    weight_ = c.ddN() * h;
    anchor_.assign(count, 0.0);
    touching_.assign(count, false);
    for (int i = 0; i < count; ++i) touching_[i] = delta_[i] < 0.0;  // in contact at the pre-load
  }
  /// Moves from a_old to a (both as the MMD sees them) and to b; returns the friction work.
  double step(double a_old, double a, double b) {
    const double d_old = a_old - a0_, d = a - a0_, d_mid = 0.5 * (d_old + d);  // exact: Sterbenz
    double dW = 0.0;
    for (std::size_t i = 0; i < delta_.size(); ++i) {
      if (!(d > delta_[i])) {
        touching_[i] = false;
        continue;
      }
      if (!touching_[i]) touching_[i] = true, anchor_[i] = b;
      const double lim = c_.tm * (d - delta_[i]);
      const double p = std::clamp(anchor_[i], b - lim, b + lim);
      dW += 2.0 * c_.p.mu * std::max(d_mid - delta_[i], 0.0) * weight_ * std::abs(p - anchor_[i]);
      anchor_[i] = p;
    }
    return dW;
  }

 private:
  const Preloaded& c_;
  double a0_;
  std::vector<double> delta_, anchor_;
  double weight_;
  std::vector<bool> touching_;
};

TEST(MmdPreloaded, NormalWigglesAgreeWithALocalSpringBed) {
  const Preloaded c;
  struct Case {
    double a0, b_star, wiggle;
  };
  // Wiggles far below, at and far above the tangential slip zone's width u = b*/θμ.
  for (const Case& k : {Case{2e-8, 2e-17, 1e-16}, Case{2e-8, 2e-17, 1e-9}, Case{1e-7, 1e-15, 1e-10},
                        Case{1e-9, 1e-13, 1e-12}, Case{1e-8, 1e-18, 1e-10}}) {
    const History h{k.a0, k.b_star, k.wiggle};
    const double reach = 2.0 * (1.001 * h.b_star / c.tm) + 2.0 * h.wiggle * h.a0;  // deepest spring that can slip
    LocalSpringBed bed(c, h.a0, -1.5 * reach - 1e-3 * reach, 1.1 * h.wiggle * h.a0 + 1e-30, 4000);
    MemoryDiagram cell;
    cell.reset(*c.law, h.a0, 0.0);
    const int n = 1000, fine = 5;
    double W_mmd = 0.0, W_bed = 0.0, a1 = h.a0, b1 = 0.0;
    for (int s = 1; s <= 3 * n; ++s) {
      const double a2 = h.a(double(s) / n), b2 = h.b(double(s) / n);
      double a_prev = a1, dW_bed = 0.0;
      for (int j = 1; j <= fine; ++j) {  // substeps of the MMD's straight step
        const double a = a1 + (a2 - a1) * j / fine;
        dW_bed += bed.step(a_prev, a, b1 + (b2 - b1) * j / fine);
        a_prev = a;
      }
      const StepResult r = cell.commit(*c.law, c.cfg, a2, b2);
      if (s > 2 * n) W_mmd += r.dW, W_bed += dW_bed;
      a1 = a2, b1 = b2;
    }
    ASSERT_GT(W_bed, 0.0);
    EXPECT_NEAR(W_mmd, W_bed, 5e-3 * W_bed) << "a0 " << k.a0 << " b* " << k.b_star << " wiggle " << k.wiggle;
  }
}

}  // namespace
}  // namespace vibrotherm::contact

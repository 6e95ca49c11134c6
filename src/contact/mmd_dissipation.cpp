// Exact friction work of the spring bed along a straight path in (a, b̃).
//
// Every spring α slips at the rate r of the wedge edge that pushes it, from the
// moment τ(α) the edge reaches it to e(α) = min(1, the moment a(t) falls below α).
// Its friction force is μ (a(t) − α) dN'(α) and its full relative slip rate 2r, so
//   ΔW = 2μ Σ_edges r ∫ P(α) dN'(α),   P(α) = ∫_τ^e (a(t) − α) dt.
// On each piece where the old diagram, τ and e are linear in α, P is a quadratic,
// and ∫ P dN' = [P N' − P' N + P'' M] (integration by parts twice): exact with
// the law values N, N', M only. The spring at α = 0 carries the atom N'(0+).
#include <algorithm>
#include <cmath>
#include <utility>

#include "mmd_detail.hpp"

namespace vibrotherm::contact::detail {
namespace {

/// An affine function of α: value v at α = x0, slope d.
struct Affine {
  double x0, v, d;
  double operator()(double x) const { return v + d * (x - x0); }
};

/// The straight step and its two wedge edges.
struct PathStep {
  double a1, bt1, da, tm;
  double r_lo, r_up;  ///< inward speeds of the lower and upper edge (> 0: pushing)
};

/// P, P', P'' at α, for edge arrival time τ and end time e (both affine).
struct PValues {
  double P, dP, ddP;
};
PValues p_values(const PathStep& st, double alpha, const Affine& tau, const Affine& e) {
  const double t = tau(alpha), E = e(alpha), c = st.a1 - alpha;
  return {c * (E - t) + 0.5 * st.da * (E * E - t * t),
          -(E - t) + c * (e.d - tau.d) + st.da * (E * e.d - t * tau.d),
          -2.0 * (e.d - tau.d) + st.da * (e.d * e.d - tau.d * tau.d)};
}

/// ∫_x^y P dN' by parts: [P N' − P' N + P'' M].
double integrate(const PathStep& st, const Affine& tau, const Affine& e, double x, const NormalLawValue& lx,
                 double y, const NormalLawValue& ly) {
  const PValues px = p_values(st, x, tau, e), py = p_values(st, y, tau, e);
  return (py.P * ly.dN - py.dP * ly.N + py.ddP * ly.M) - (px.P * lx.dN - px.dP * lx.N + px.ddP * lx.M);
}

/// Contribution of the springs on [l, r] of one old segment (diagram g affine there).
double segment_work(const PathStep& st, const NormalLaw& law, const Affine& g, double l, const NormalLawValue& law_l,
                    double r, const NormalLawValue& law_r, double a2) {
  // Edge arrival times: the lower edge b̃(t) − θμ(a(t) − α) rises at r_lo, the
  // upper one falls at r_up; τ = distance at t = 0 / speed.
  const bool lo_on = st.r_lo > 0.0, up_on = st.r_up > 0.0;
  const Affine tau_lo = lo_on ? Affine{l, (g(l) - st.bt1 + st.tm * (st.a1 - l)) / st.r_lo, (g.d - st.tm) / st.r_lo}
                              : Affine{l, INFINITY, 0.0};
  const Affine tau_up = up_on ? Affine{l, (st.bt1 + st.tm * (st.a1 - l) - g(l)) / st.r_up, (-st.tm - g.d) / st.r_up}
                              : Affine{l, INFINITY, 0.0};
  const Affine one{l, 1.0, 0.0};
  // Detachment time (a(t) = α), for springs above a2 when a decreases.
  const Affine detach = st.da < 0.0 ? Affine{l, (st.a1 - l) / -st.da, 1.0 / st.da} : one;

  // Cut [l, r] where the end-time branch or the pushing edge changes or τ crosses e.
  double cuts[8];
  int nc = 0;
  cuts[nc++] = l;
  cuts[nc++] = r;
  if (st.da < 0.0 && a2 > l && a2 < r) cuts[nc++] = a2;
  auto add_root = [&](const Affine& u, const Affine& v) {
    const double fl = u(l) - v(l), fr = u(r) - v(r);
    if (std::isfinite(fl) && std::isfinite(fr) && fl * fr < 0.0) cuts[nc++] = l + (r - l) * fl / (fl - fr);
  };
  if (lo_on && up_on) add_root(tau_lo, tau_up);
  for (const Affine* tau : {&tau_lo, &tau_up}) {
    add_root(*tau, one);
    if (st.da < 0.0) add_root(*tau, detach);
  }
  for (int i = 1; i < nc; ++i)  // insertion sort: at most 8 cuts
    for (int k = i; k > 0 && cuts[k] < cuts[k - 1]; --k) std::swap(cuts[k], cuts[k - 1]);

  double work = 0.0;
  for (int k = 0; k + 1 < nc; ++k) {
    const double x = cuts[k], y = cuts[k + 1];
    if (!(y > x)) continue;
    const double c = 0.5 * (x + y);
    const Affine& e = (st.da < 0.0 && c > a2) ? detach : one;
    const bool use_lo = tau_lo(c) <= tau_up(c);
    const Affine& tau = use_lo ? tau_lo : tau_up;
    if (!(tau(c) < e(c))) continue;  // the edge never reaches these springs
    const NormalLawValue lx = x == l ? law_l : law.eval(x);
    const NormalLawValue ly = y == r ? law_r : law.eval(y);
    // Each spring's work is >= 0; clamp the rounding of the by-parts difference.
    work += (use_lo ? st.r_lo : st.r_up) * std::max(0.0, integrate(st, tau, e, x, lx, y, ly));
  }
  return work;
}

}  // namespace

double path_dissipation(const Breakpoint* pts, std::size_t n, const NormalLaw& law, const MmdConfig& cfg, double a2,
                        double bt2, const Tail& tail) {
  const double q_final = tail.q;
  const double tm = cfg.theta * cfg.mu;
  const double a1 = pts[n - 1].alpha, bt1 = pts[n - 1].f;
  const double da = a2 - a1, db = bt2 - bt1;
  const PathStep st{a1, bt1, da, tm, db - tm * da, -db - tm * da};
  if (!(st.r_lo > 0.0) && !(st.r_up > 0.0)) return 0.0;  // both edges move away: pure stick
  double work = 0.0;

  // Springs born during the step (a grows) sit on the pushing edge from birth:
  // P(α) = (a2 − α)² / (2Δa).
  if (da > 0.0) {
    const double r = st.r_lo > 0.0 ? st.r_lo : st.r_up;
    const NormalLawValue& l2 = tail.apex;
    const NormalLawValue& l1 = pts[n - 1].law;
    // At a2: P = P' = 0, so only P''M remains there.
    const double P1 = 0.5 * da, dP1 = -1.0, ddP = 1.0 / da;
    work += r * std::max(0.0, ddP * l2.M - (P1 * l1.dN - dP1 * l1.N + ddP * l1.M));
  }

  // Springs already in contact, walking the old diagram down from a1 to q_final
  // (below q_final nothing slips; above a2 springs may slip before detaching).
  for (std::size_t k = n - 1; k-- > 0;) {
    const Breakpoint &A = pts[k], &B = pts[k + 1];
    if (B.alpha <= q_final) break;
    const Affine g{A.alpha, A.f, (B.f - A.f) / (B.alpha - A.alpha)};
    const double l = std::max(A.alpha, q_final);
    const NormalLawValue law_l = l == A.alpha ? A.law : (tail.has_q_value && l == tail.q ? tail.at_q : law.eval(l));
    work += segment_work(st, law, g, l, law_l, B.alpha, B.law, a2);
  }

  // The spring at α = 0 of a law with N'(0+) > 0 (flat contact): it slips when
  // the whole diagram slides.
  const double k0 = law.stiffness_at_zero();
  if (k0 > 0.0 && q_final <= 0.0) {
    const Affine one{0.0, 1.0, 0.0};
    const double t_lo = st.r_lo > 0.0 ? (-bt1 + tm * a1) / st.r_lo : INFINITY;
    const double t_up = st.r_up > 0.0 ? (bt1 + tm * a1) / st.r_up : INFINITY;
    const bool use_lo = t_lo <= t_up;
    const double t0 = std::max(0.0, std::min(t_lo, t_up));
    if (t0 < 1.0) {
      const Affine tau{0.0, t0, 0.0};
      work += (use_lo ? st.r_lo : st.r_up) * k0 * p_values(st, 0.0, tau, one).P;
    }
  }
  return 2.0 * cfg.mu * work;
}

}  // namespace vibrotherm::contact::detail

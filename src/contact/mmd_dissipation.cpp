// Exact friction work of the spring bed along a straight path in (a, b̃).
//
// Every spring α slips at the rate r of the wedge edge that pushes it, from the
// moment τ(α) the edge reaches it to e(α) = min(1, the moment a(t) falls below α).
// Its friction force is μ (a(t) − α) dN'(α) and its full relative slip rate 2r, so
//   ΔW = 2μ Σ_edges r ∫ P(α) dN'(α),   P(α) = ∫_τ^e (a(t) − α) dt.
// On each piece where the old diagram, τ and e are affine in α, P is a quadratic,
// and ∫ P dN' = P(x) m0 + P'(x) m1 + P''(x) m2 / 2 with the law's moments
// m_k = ∫_x^y (α − x)^k dN' of the piece [x, y]. Every term is bounded by
// max P · m0 (P >= 0 on the piece), so nothing cancels: a step dissipates what
// its springs' slips dissipate, to rounding of that amount, however small the
// step (the antiderivative form [P N' − P' N + P'' M] this replaces subtracted
// terms of size M/Δa and dissipated 1e-9 J/m² from rounding, issue 23).
// The spring at α = 0 carries the atom N'(0+) and is counted once, on its own.
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

/// P on one piece, as its value and derivatives at the piece's left end x.
struct Quadratic {
  double P, dP, ddP;
};
Quadratic p_at(const PathStep& st, double x, const Affine& tau, const Affine& e) {
  const double t = tau(x), E = e(x);
  const double gap = st.a1 - x + 0.5 * st.da * (E + t);  // mean of a(t) − x over [t, E]
  const double dgap = -1.0 + 0.5 * st.da * (e.d + tau.d);
  return {(E - t) * gap, (e.d - tau.d) * gap + (E - t) * dgap, 2.0 * (e.d - tau.d) * dgap};
}

/// ∫_x^y P dN' for a quadratic P given at x.
double integrate(const NormalLaw& law, const Quadratic& p, double x, const NormalLawValue& lx, double y,
                 const NormalLawValue& ly) {
  const DensityMoments m = law.density_moments(x, lx, y, ly);
  return p.P * m.m0 + p.dP * m.m1 + 0.5 * p.ddP * m.m2;
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

  // Cut [l, r] where the end-time branch or the pushing edge changes, τ crosses e, or τ
  // crosses 0 (a point of the diagram outside the wedge by rounding: it rides the edge from t = 0).
  const Affine zero{l, 0.0, 0.0};
  double cuts[12];
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
    add_root(*tau, zero);
    if (st.da < 0.0) add_root(*tau, detach);
  }
  for (int i = 1; i < nc; ++i)  // insertion sort: at most 12 cuts
    for (int k = i; k > 0 && cuts[k] < cuts[k - 1]; --k) std::swap(cuts[k], cuts[k - 1]);

  double work = 0.0;
  for (int k = 0; k + 1 < nc; ++k) {
    const double x = cuts[k], y = cuts[k + 1];
    if (!(y > x)) continue;
    const double c = 0.5 * (x + y);
    const Affine& e = (st.da < 0.0 && c > a2) ? detach : one;
    const bool use_lo = tau_lo(c) <= tau_up(c);
    const Affine& tau = (use_lo ? tau_lo : tau_up)(c) < 0.0 ? zero : (use_lo ? tau_lo : tau_up);
    if (!(tau(c) < e(c))) continue;  // the edge never reaches these springs
    const NormalLawValue lx = x == l ? law_l : law.eval(x);
    const NormalLawValue ly = y == r ? law_r : law.eval(y);
    // Each spring's work is >= 0; clamp the rounding of the sum.
    work += (use_lo ? st.r_lo : st.r_up) * std::max(0.0, integrate(law, p_at(st, x, tau, e), x, lx, y, ly));
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
  // P(α) = (a2 − α)² / (2Δa), i.e. Δa/2, −1, 1/Δa at a1.
  if (da > 0.0) {
    const double r = st.r_lo > 0.0 ? st.r_lo : st.r_up;
    work += r * std::max(0.0, integrate(law, {0.5 * da, -1.0, 1.0 / da}, a1, pts[n - 1].law, a2, tail.apex));
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
      work += (use_lo ? st.r_lo : st.r_up) * k0 * p_at(st, 0.0, tau, one).P;
    }
  }
  return 2.0 * cfg.mu * work;
}

}  // namespace vibrotherm::contact::detail

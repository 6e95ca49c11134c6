// Memory-diagram update (PHYSICS.md §3.3): contact loss, total sliding, and
// partial slip by clipping the old diagram to the new wedge.
#include "vibrotherm/contact/memory_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mmd_detail.hpp"

namespace vibrotherm::contact {

using detail::Breakpoint;
using detail::Tail;

const char* to_string(ContactState state) {
  switch (state) {
    case ContactState::Loss: return "loss";
    case ContactState::Slide: return "slide";
    case ContactState::Partial: return "partial";
    case ContactState::Stick: return "stick";
  }
  return "?";
}

namespace detail {

namespace {
double slope(const Breakpoint& p, const Breakpoint& q) { return (q.f - p.f) / (q.alpha - p.alpha); }

/// Where the old diagram meets the new wedge: its apex (a1, b̃1), m = min(a1, a2),
/// the last old point j at or below m and the diagram's value g_m at m.
struct Clip {
  double tm, inv_theta, a1, bt1, m, eps_alpha, g_m;
  std::size_t j;
  bool inside;  ///< m lies strictly inside segment j (not on point j)
};

Clip clip_at(const Breakpoint* pts, std::size_t n, const MmdConfig& cfg, double a2) {
  Clip c;
  c.tm = cfg.theta * cfg.mu;
  c.inv_theta = 1.0 / cfg.theta;
  c.a1 = pts[n - 1].alpha, c.bt1 = pts[n - 1].f;
  c.m = std::min(c.a1, a2);
  c.eps_alpha = cfg.rel_tol * a2;
  // j: last old point with α_j <= m (the points above m detach).
  c.j = n - 1;
  while (c.j > 0 && pts[c.j].alpha > c.m) --c.j;
  c.inside = c.j + 1 < n && c.m > pts[c.j].alpha;
  const double sigma_j = c.inside ? slope(pts[c.j], pts[c.j + 1]) : 0.0;
  c.g_m = c.inside ? pts[c.j].f + sigma_j * (c.m - pts[c.j].alpha) : pts[c.j].f;
  return c;
}

/// Nothing slips: keep the old diagram up to m, then follow the path.
void stick_tail(const Breakpoint* pts, std::size_t n, const Clip& c, double a2, double bt2, Tail* tail) {
  tail->state = ContactState::Stick;
  tail->keep = c.j + 1;
  tail->q = c.m;
  double T = pts[c.j].T_before;
  const double alpha_prev = pts[c.j].alpha, f_prev = pts[c.j].f, N_prev = pts[c.j].law.N;
  if (a2 > c.a1) {
    T += c.inv_theta * (bt2 - c.bt1) / (a2 - c.a1) * (tail->N - pts[n - 1].law.N);
  } else if (a2 > alpha_prev + c.eps_alpha) {
    T += c.inv_theta * (bt2 - f_prev) / (a2 - alpha_prev) * (tail->N - N_prev);
  } else {
    // a2 sits on point j (j >= 1 since a2 > 0): the apex replaces it, snapped onto b̃2.
    tail->keep = c.j;
    const Breakpoint& p = pts[c.j - 1];
    T = p.T_before + c.inv_theta * (bt2 - p.f) / (a2 - p.alpha) * (tail->N - p.law.N);
  }
  tail->count = 1;
  tail->alpha[0] = a2;
  tail->f[0] = bt2;
  tail->T = T;
}

/// Partial slip: the active slip line f = L + s·θμ·α. In h = s f − θμ α (never
/// increasing along the diagram) the violated points are those with h < s L,
/// always a run at the right end: pop them, then intersect.
void partial_tail(const Breakpoint* pts, const NormalLaw& law, const MmdConfig& cfg, const Clip& c, double a2,
                  double bt2, Tail* tail) {
  tail->state = ContactState::Partial;
  const int s = tail->s;
  const double tm = c.tm;
  const double L = bt2 - s * tm * a2, sL = s * bt2 - tm * a2;
  auto h = [&](double alpha, double f) { return s * f - tm * alpha; };
  double alpha_next = c.m, f_next = c.g_m;
  std::size_t i = c.j;
  if (!c.inside) {  // m coincides with point j, which is violated
    alpha_next = pts[c.j].alpha;
    f_next = pts[c.j].f;
    i = c.j - 1;  // j > 0: h_0 = 0 >= sL when not sliding
  }
  while (i > 0 && h(pts[i].alpha, pts[i].f) < sL) {
    alpha_next = pts[i].alpha;
    f_next = pts[i].f;
    --i;
  }
  const double h_i = h(pts[i].alpha, pts[i].f), h_next = h(alpha_next, f_next);
  double q = pts[i].alpha;
  if (h_i > sL && h_i > h_next) q = pts[i].alpha + (h_i - sL) / (h_i - h_next) * (alpha_next - pts[i].alpha);
  q = std::min(q, a2);
  tail->keep = i + 1;
  tail->q = q;
  const double sigma = (f_next - pts[i].f) / (alpha_next - pts[i].alpha);
  double T = pts[i].T_before;
  if (q > pts[i].alpha + c.eps_alpha && q < a2 - c.eps_alpha) {
    tail->at_q = law.eval(q);
    tail->has_q_value = true;
    const NormalLawValue& at_q = tail->at_q;
    T += c.inv_theta * sigma * (at_q.N - pts[i].law.N) + s * cfg.mu * (tail->N - at_q.N);
    tail->alpha[tail->count] = q;
    tail->f[tail->count++] = L + s * tm * q;
  } else {
    T += c.inv_theta * (bt2 - pts[i].f) / (a2 - pts[i].alpha) * (tail->N - pts[i].law.N);
  }
  tail->alpha[tail->count] = a2;
  tail->f[tail->count++] = bt2;
  tail->T = T;
}

}  // namespace

Tail build_tail(const Breakpoint* pts, std::size_t n, const NormalLaw& law, const MmdConfig& cfg, double a2,
                double bt2) {
  Tail tail;
  if (!(a2 > 0.0)) return tail;  // contact loss
  const double tm = cfg.theta * cfg.mu;
  tail.apex = law.eval(a2);
  tail.N = tail.apex.N;
  // Total sliding: the trial b̃ lies outside the wedge at α = 0.
  if (std::abs(bt2) >= tm * a2) {
    tail.state = ContactState::Slide;
    tail.s = bt2 >= 0.0 ? 1 : -1;
    tail.keep = 1;
    tail.count = 1;
    tail.alpha[0] = a2;
    tail.f[0] = tail.s * tm * a2;
    tail.T = tail.s * cfg.mu * tail.N;
    tail.q = 0.0;
    return tail;
  }
  const Clip c = clip_at(pts, n, cfg, a2);
  const double tol_f = cfg.rel_tol * tm * a2;
  const double lo_m = bt2 - tm * (a2 - c.m), hi_m = bt2 + tm * (a2 - c.m);
  tail.s = c.g_m < lo_m - tol_f ? 1 : (c.g_m > hi_m + tol_f ? -1 : 0);
  if (tail.s == 0) stick_tail(pts, n, c, a2, bt2, &tail);
  else partial_tail(pts, law, cfg, c, a2, bt2, &tail);
  return tail;
}

}  // namespace detail

namespace {
/// The single point of a virgin diagram at a = 0.
Breakpoint virgin_point() { return Breakpoint{0.0, 0.0, NormalLawValue{}, 0.0}; }
}  // namespace

void MemoryDiagram::reset(const NormalLaw& law, double a, double b) {
  pts_.clear();
  a_ = a;
  b_ = b;
  b0_ = b;
  if (a > 0.0) {
    pts_.push_back(virgin_point());
    pts_.push_back(Breakpoint{a, 0.0, law.eval(a), 0.0});
  }
}

Traction MemoryDiagram::trial(const NormalLaw& law, const MmdConfig& cfg, double a, double b) const {
  if (!(a > 0.0)) return {};
  if (pts_.empty()) {  // entering contact inside the step: virgin at a = 0
    const double bc = b_ + (0.0 - a_) / (a - a_) * (b - b_);
    const Breakpoint v = virgin_point();
    const Tail tail = detail::build_tail(&v, 1, law, cfg, a, b - bc);
    return {tail.N, Tangential(tail.T)};
  }
  const Tail tail = detail::build_tail(pts_.data(), pts_.size(), law, cfg, a, b - b0_);
  return {tail.N, Tangential(tail.T)};
}

StepResult MemoryDiagram::commit(const NormalLaw& law, const MmdConfig& cfg, double a2, double b2) {
  StepResult result;
  if (pts_.empty()) {
    if (!(a2 > 0.0)) {  // still apart: the faces move freely
      a_ = a2;
      b_ = b0_ = b2;
      return result;
    }
    // Contact starts inside the step, at a = 0: the path continues from a virgin state there.
    const double bc = b_ + (0.0 - a_) / (a2 - a_) * (b2 - b_);
    pts_.push_back(virgin_point());
    a_ = 0.0;
    b_ = b0_ = bc;
  }
  const double a1 = a_, b1 = b_;
  if (!(a2 > 0.0)) {  // contact lost inside the step, at a = 0
    const double b_end = b1 + a1 / (a1 - a2) * (b2 - b1);
    Tail to_zero;  // ends at a = 0: everything detaches, nothing is left below
    to_zero.q = 0.0;
    result.dW = detail::path_dissipation(pts_.data(), pts_.size(), law, cfg, 0.0, b_end - b0_, to_zero);
    pts_.clear();
    a_ = a2;
    b_ = b0_ = b2;
    return result;
  }
  const double bt2 = b2 - b0_;
  const Tail tail = detail::build_tail(pts_.data(), pts_.size(), law, cfg, a2, bt2);
  result.dW = detail::path_dissipation(pts_.data(), pts_.size(), law, cfg, a2, bt2, tail);
  result.N = tail.N;
  result.T = Tangential(tail.T);
  result.state = tail.state;

  pts_.resize(tail.keep);
  for (int k = 0; k < tail.count; ++k) {
    const bool apex = k + 1 == tail.count, at_q = tail.has_q_value && tail.alpha[k] == tail.q;
    push_point(law, cfg, tail.alpha[k], tail.f[k], apex ? &tail.apex : (at_q ? &tail.at_q : nullptr));
  }
  if (tail.state == ContactState::Slide) b0_ = b2 - tail.f[0];
  a_ = a2;
  b_ = b2;
  enforce_memory_bound(cfg);
  return result;
}

void MemoryDiagram::push_point(const NormalLaw& law, const MmdConfig& cfg, double alpha, double f,
                               const NormalLawValue* value) {
  // Merge with the previous segment when collinear (keeps the stack short).
  const std::size_t n = pts_.size();
  if (n >= 2) {
    const Breakpoint &p = pts_[n - 2], &q = pts_[n - 1];
    const double s1 = (q.f - p.f) / (q.alpha - p.alpha), s2 = (f - q.f) / (alpha - q.alpha);
    if (std::abs(s1 - s2) <= 1e-12 * cfg.theta * cfg.mu + 1e-300) pts_.pop_back();
  }
  const Breakpoint& last = pts_.back();
  const NormalLawValue v = value ? *value : law.eval(alpha);
  const double T_before = last.T_before + (f - last.f) / (alpha - last.alpha) * (v.N - last.law.N) / cfg.theta;
  pts_.push_back(Breakpoint{alpha, f, v, T_before});
}

void MemoryDiagram::enforce_memory_bound(const MmdConfig& cfg) {
  // Drop the interior point whose removal changes the diagram least (smallest
  // triangle area). The chord stays inside the wedge (a convex cone), so the
  // diagram stays admissible; only stored energy changes, by a tiny amount.
  while (pts_.size() > std::max<std::size_t>(cfg.max_breakpoints, 3)) {
    std::size_t best = 1;
    double best_area = INFINITY;
    for (std::size_t k = 1; k + 1 < pts_.size(); ++k) {
      const Breakpoint &p = pts_[k - 1], &q = pts_[k], &r = pts_[k + 1];
      const double area = std::abs((r.alpha - p.alpha) * (q.f - p.f) - (q.alpha - p.alpha) * (r.f - p.f));
      if (area < best_area) best_area = area, best = k;
    }
    pts_.erase(pts_.begin() + static_cast<std::ptrdiff_t>(best));
    for (std::size_t k = best; k < pts_.size(); ++k) {
      const Breakpoint& p = pts_[k - 1];
      Breakpoint& q = pts_[k];
      q.T_before = p.T_before + (q.f - p.f) / (q.alpha - p.alpha) * (q.law.N - p.law.N) / cfg.theta;
    }
  }
}

double MemoryDiagram::stored_energy(const MmdConfig& cfg) const {
  if (pts_.empty()) return 0.0;
  const double bt = b_ - b0_;
  double Ut = 0.0;
  for (std::size_t k = 0; k + 1 < pts_.size(); ++k) {
    const Breakpoint &A = pts_[k], &B = pts_[k + 1];
    // m (bt − f_A) ΔN + m² ∫_A^B (N − N_B) dα: the same sum as with the line through A,
    // without the two m²·α_A·ΔN terms that cancel. The integral, M_B − M_A − Δα N_B, is
    // O(Δα²) from O(Δα) parts: on a segment much shorter than α it would keep no digit,
    // and there the trapezoid rule −Δα ΔN / 2 is exact to O(Δα/α).
    const double dalpha = B.alpha - A.alpha, m = (B.f - A.f) / dalpha, dN = B.law.N - A.law.N;
    const double integral = std::abs(dalpha) < 1e-4 * std::abs(B.alpha) ? -0.5 * dalpha * dN
                                                                          : (B.law.M - A.law.M) - dalpha * B.law.N;
    Ut += m * (bt - A.f) * dN + m * m * integral;
  }
  return 2.0 * pts_.back().law.M + 2.0 * Ut / cfg.theta;
}

}  // namespace vibrotherm::contact

namespace vibrotherm::contact {

namespace {
constexpr std::size_t kHeader = 3, kPerPoint = 6;  // a, b, b0; α, f, N, N', M, T_before
}

std::vector<double> MemoryDiagram::save() const {
  std::vector<double> values = {a_, b_, b0_};
  for (const Breakpoint& p : pts_) values.insert(values.end(), {p.alpha, p.f, p.law.N, p.law.dN, p.law.M, p.T_before});
  return values;
}

void MemoryDiagram::restore(const double* values, std::size_t n) {
  if (n < kHeader || (n - kHeader) % kPerPoint != 0)
    throw std::runtime_error("memory diagram: a saved state of " + std::to_string(n) + " values is malformed");
  a_ = values[0], b_ = values[1], b0_ = values[2];
  pts_.clear();
  for (const double* p = values + kHeader; p < values + n; p += kPerPoint) {
    Breakpoint b;
    b.alpha = p[0], b.f = p[1], b.law.N = p[2], b.law.dN = p[3], b.law.M = p[4], b.T_before = p[5];
    pts_.push_back(b);
  }
}

}  // namespace vibrotherm::contact

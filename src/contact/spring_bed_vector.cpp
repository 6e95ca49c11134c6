// The vector spring bed (MMD with two tangential components, PHYSICS.md §3.5).
#include "vibrotherm/contact/spring_bed_vector.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vibrotherm::contact {

namespace {

using Level = VectorSpringBed::Level;

/// x + t (y − x), component by component.
Tangential along(const Tangential& x, const Tangential& y, double t) {
  Tangential z = x;
  for (int k = 0; k < x.components(); ++k) z[k] = x[k] + t * (y[k] - x[k]);
  return z;
}

/// Level j of spacing h: the weight ∫ N'' on (j h, (j+1) h] at its N''-centroid
/// (the atom N'(0+) is not part of it).
Level level_at(const NormalLaw& law, double h, std::size_t j, const Tangential& anchor) {
  const double x = static_cast<double>(j) * h, y = static_cast<double>(j + 1) * h;
  const DensityMoments m = law.density_moments(x, law.eval(x), y, law.eval(y));
  Level level;
  level.weight = m.m0;
  level.alpha = m.m0 > 0.0 ? std::clamp(x + m.m1 / m.m0, x, y) : 0.5 * (x + y);
  level.anchor = anchor;
  return level;
}

struct SpringMove {
  Tangential anchor;
  double work = 0.0;
  bool slipped = false;
};

/// One spring (α, w) from anchor p towards the tangential position `target`:
/// stuck inside the disk of radius θμ(a2 − α)⁺, else returned radially onto it.
SpringMove move_spring(const Tangential& p, double alpha, double weight, double a1, double a2,
                       const Tangential& target, const SpringBedConfig& cfg) {
  const double radius = cfg.theta * cfg.mu * std::max(a2 - alpha, 0.0);
  const double gap = distance(target, p);
  if (!(gap > radius)) return {p, 0.0, false};
  SpringMove move{target, 0.0, true};
  for (int k = 0; k < p.components(); ++k) move.anchor[k] = target[k] - radius * (target[k] - p[k]) / gap;
  // Friction force μ w (a − α), trapezoid in a: exact at constant a.
  const double arm = std::max(a1 - alpha, 0.0) + std::max(a2 - alpha, 0.0);
  move.work = cfg.mu * weight * arm * distance(move.anchor, p);
  return move;
}

}  // namespace

struct VectorSpringBed::Sweep {
  Tangential sum;          ///< Σ w (b2 − p) over the springs in contact at the end
  Tangential atom_anchor;  ///< the atom's new anchor
  double dW = 0.0;
  bool atom_slipped = false, any_slipped = false;
  std::size_t in_contact = 0;  ///< levels in contact at the end (a prefix)
};

double VectorSpringBed::spacing_for(const SpringBedConfig& cfg, double a2) const {
  return h_ > 0.0 ? h_ : 2.0 * a2 / cfg.levels;
}

/// Moves every spring touching during the step to (a2, b2); on_level(j, level)
/// receives each level in contact at the end, in order.
template <class OnLevel>
VectorSpringBed::Sweep VectorSpringBed::sweep(const NormalLaw& law, const SpringBedConfig& cfg, double a2,
                                              const Tangential& b2, OnLevel on_level) const {
  Sweep s;
  s.sum = Tangential::zero(b2.components());
  s.atom_anchor = b2;
  const double a1 = a_;
  // Where the straight path crosses a = α: springs enter and leave contact there.
  auto crossing = [&](double alpha) { return along(b_, b2, (alpha - a1) / (a2 - a1)); };
  auto visit = [&](const Tangential& p, double alpha, double weight) {
    const bool ends_in_contact = a2 > alpha;
    const SpringMove m =
        move_spring(p, alpha, weight, a1, a2, ends_in_contact ? b2 : crossing(alpha), cfg);
    s.dW += m.work;
    if (ends_in_contact) {
      s.any_slipped = s.any_slipped || m.slipped;
      for (int k = 0; k < b2.components(); ++k) s.sum[k] += weight * (b2[k] - m.anchor[k]);
    }
    return m;
  };
  if (!(a1 > 0.0) && !(a2 > 0.0)) return s;
  const SpringMove atom = visit(a1 > 0.0 ? atom_anchor_ : crossing(0.0), 0.0, law.stiffness_at_zero());
  if (a2 > 0.0) s.atom_anchor = atom.anchor, s.atom_slipped = atom.slipped;
  for (std::size_t j = 0; j < levels_.size(); ++j) {
    Level level = levels_[j];
    level.anchor = visit(level.anchor, level.alpha, level.weight).anchor;
    if (a2 > level.alpha) on_level(s.in_contact++, level);
  }
  if (!(a2 > a1)) return s;
  const double h = spacing_for(cfg, a2);
  for (std::size_t j = levels_.size();; ++j) {  // springs entering contact, stuck where they touch
    Level level = level_at(law, h, j, b2);
    if (!(level.alpha < a2)) break;
    level.anchor = visit(crossing(level.alpha), level.alpha, level.weight).anchor;
    on_level(s.in_contact++, level);
  }
  return s;
}

void VectorSpringBed::reset(const NormalLaw& law, const SpringBedConfig& cfg, double a, const Tangential& b) {
  a_ = a;
  b_ = atom_anchor_ = b;
  levels_.clear();
  h_ = a > 0.0 ? 2.0 * a / cfg.levels : 0.0;
  if (!(a > 0.0)) return;
  for (std::size_t j = 0;; ++j) {
    const Level level = level_at(law, h_, j, b);
    if (!(level.alpha < a)) break;
    levels_.push_back(level);
  }
  while (levels_.size() > static_cast<std::size_t>(cfg.levels)) coarsen(law);
}

namespace {
ContactState state_of(double a2, bool atom_slipped, bool any_slipped) {
  if (!(a2 > 0.0)) return ContactState::Loss;
  if (atom_slipped) return ContactState::Slide;  // the spring at α = 0 slips: |b̃| ≥ θμa in 2D
  return any_slipped ? ContactState::Partial : ContactState::Stick;
}

Tangential traction_of(const Tangential& sum, double theta) {
  Tangential T = sum;
  for (int k = 0; k < T.components(); ++k) T[k] = sum[k] / theta;
  return T;
}
}  // namespace

void VectorSpringBed::cover(const NormalLaw& law, const SpringBedConfig& cfg, double a2) {
  // Before the step, so that a jump in a never creates more than L levels.
  while (h_ > 0.0 && a2 > cfg.levels * h_) coarsen(law);
}

Traction VectorSpringBed::trial(const NormalLaw& law, const SpringBedConfig& cfg, double a,
                                const Tangential& b) const {
  if (!(a > 0.0)) return {0.0, Tangential::zero(b.components())};
  if (h_ > 0.0 && a > cfg.levels * h_) {  // rare: the step coarsens first, as commit does
    VectorSpringBed covering = *this;
    covering.cover(law, cfg, a);
    return covering.trial(law, cfg, a, b);
  }
  const Sweep s = sweep(law, cfg, a, b, [](std::size_t, const Level&) {});
  return {law.eval(a).N, traction_of(s.sum, cfg.theta)};
}

StepResult VectorSpringBed::commit(const NormalLaw& law, const SpringBedConfig& cfg, double a2,
                                   const Tangential& b2) {
  cover(law, cfg, a2);
  const double h = spacing_for(cfg, a2);
  // Levels are visited in order and each is read before it is written: update in place.
  const Sweep s = sweep(law, cfg, a2, b2, [this](std::size_t j, const Level& level) {
    if (j < levels_.size()) levels_[j] = level;
    else levels_.push_back(level);
  });
  levels_.resize(s.in_contact);
  StepResult r;
  r.dW = s.dW;
  r.T = Tangential::zero(b2.components());
  r.state = state_of(a2, s.atom_slipped, s.any_slipped);
  a_ = a2;
  b_ = b2;
  atom_anchor_ = s.atom_anchor;
  if (a2 > 0.0) h_ = h;  // kept through contact loss: the grid of the largest approach seen
  if (a2 > 0.0) {
    r.N = law.eval(a2).N;
    r.T = traction_of(s.sum, cfg.theta);
  }
  return r;
}

void VectorSpringBed::coarsen(const NormalLaw& law) {
  // Pairs (2i, 2i+1) become level i of spacing 2h, anchored at their weighted
  // mean; a partner out of contact has its anchor at b.
  const double h2 = 2.0 * h_;
  std::vector<Level> merged;
  for (std::size_t i = 0; 2 * i < levels_.size(); ++i) {
    Level level = level_at(law, h2, i, b_);
    if (!(level.alpha < a_)) break;
    const Level& low = levels_[2 * i];
    const bool high_in = 2 * i + 1 < levels_.size();
    const Tangential& p_high = high_in ? levels_[2 * i + 1].anchor : b_;
    const double w_low = low.weight, w_high = high_in ? levels_[2 * i + 1].weight : level.weight - low.weight;
    level.anchor = low.anchor;
    if (w_low + w_high > 0.0)
      for (int k = 0; k < b_.components(); ++k)
        level.anchor[k] = (w_low * low.anchor[k] + w_high * p_high[k]) / (w_low + w_high);
    merged.push_back(level);
  }
  levels_.swap(merged);
  h_ = h2;
}

double VectorSpringBed::stored_energy(const NormalLaw& law, const SpringBedConfig& cfg) const {
  if (!(a_ > 0.0)) return 0.0;
  const double atom = distance(b_, atom_anchor_);
  double springs = law.stiffness_at_zero() * atom * atom;
  for (const Level& level : levels_) {
    const double v = distance(b_, level.anchor);
    springs += level.weight * v * v;
  }
  return 2.0 * law.eval(a_).M + springs / cfg.theta;
}

namespace {
constexpr std::size_t kHeader = 6;  // a, h, b (2), the atom's anchor (2)
}

std::vector<double> VectorSpringBed::save() const {
  std::vector<double> values = {a_, h_, b_[0], b_[1], atom_anchor_[0], atom_anchor_[1]};
  for (const Level& level : levels_) values.insert(values.end(), {level.anchor[0], level.anchor[1]});
  return values;
}

void VectorSpringBed::restore(const NormalLaw& law, const double* values, std::size_t n) {
  if (n < kHeader || (n - kHeader) % 2 != 0)
    throw std::runtime_error("mmd spring bed: a saved state of " + std::to_string(n) + " values is malformed");
  a_ = values[0], h_ = values[1];
  b_ = Tangential(values[2], values[3]);
  atom_anchor_ = Tangential(values[4], values[5]);
  levels_.clear();
  for (std::size_t j = 0; kHeader + 2 * j < n; ++j)
    levels_.push_back(level_at(law, h_, j, Tangential(values[kHeader + 2 * j], values[kHeader + 2 * j + 1])));
}

}  // namespace vibrotherm::contact

// The MMD's 3D rule (PHYSICS.md §3.5): the spring bed of §3.3 with vector
// anchors, for one contact cell with two tangential components.
//
// Spring α (normal force (a − α) dN'(α), tangential stiffness dN'(α)/θ) has a
// 2D anchor p(α); it sticks while |b − p(α)| ≤ θμ(a − α) and is otherwise
// returned radially onto that disk. T = (1/θ) Σ w (b − p); springs out of
// contact (α ≥ a) have p = b. For a fixed tangential direction this is the
// scalar memory diagram as the levels are refined.
//
// Discretisation: levels j on the cells [j h, (j+1) h] of α, weight
// w_j = ∫ N'' over the cell, placed at the cell's N''-centroid (so the bed's
// normal force Σ w (a − α)⁺ is N(a) exactly for cells wholly in contact and
// never above it: |T| ≤ μN), plus the atom N'(0+) at α = 0. h = 2a/L at first
// contact (a in mid-range), kept through contact loss; before a step to an a
// past L levels, h doubles (as often as needed) and pairs of levels merge
// (anchors averaged by weight: a cell's first loading from a small a loses
// some stored energy there, once). So at most L levels per cell: state 2
// numbers per level, the atom's anchor, a, b and h (save(): 6 + 2n, n ≤ L).
//
// A step from (a1, b1) to (a2, b2): a spring entering contact starts stuck
// where the straight path reaches a = α; one leaving contact slips to where
// the path leaves a = α; the others return radially at the end of the step.
// Friction work per spring μ w [(a1 − α)⁺ + (a2 − α)⁺] |Δp|: exact at constant a
// for the dog-leg path radial return solves (as coulomb).
#pragma once

#include <cstddef>
#include <vector>

#include "vibrotherm/contact/memory_diagram.hpp"
#include "vibrotherm/contact/normal_law.hpp"
#include "vibrotherm/contact/tangential.hpp"

namespace vibrotherm::contact {

struct SpringBedConfig {
  double mu = 1.0;
  double theta = 1.0;
  int levels = 256;  ///< L, the most levels a cell keeps
};

class VectorSpringBed {
 public:
  /// Virgin state at (a, b): every spring in contact stuck at b.
  void reset(const NormalLaw& law, const SpringBedConfig& cfg, double a, const Tangential& b);

  /// Tractions at (a, b) from the committed state; the state is unchanged.
  Traction trial(const NormalLaw& law, const SpringBedConfig& cfg, double a, const Tangential& b) const;
  /// Advances the committed state to (a, b) and returns tractions and ΔW.
  StepResult commit(const NormalLaw& law, const SpringBedConfig& cfg, double a, const Tangential& b);

  /// U = 2M(a) + (1/θ) Σ w |b − p|² [J/m²].
  double stored_energy(const NormalLaw& law, const SpringBedConfig& cfg) const;
  /// The anchor of the spring at α = 0: b0 of the 2D diagram (f(0) = 0); b out of contact.
  const Tangential& slip_offset() const { return atom_anchor_; }
  std::size_t levels_in_contact() const { return levels_.size(); }

  /// a, h, b, the atom's anchor, then each level's anchor; restore recomputes
  /// the levels' α and weights from h (bit for bit); std::runtime_error on a
  /// state of the wrong shape.
  std::vector<double> save() const;
  void restore(const NormalLaw& law, const double* values, std::size_t n);

  struct Level {
    double alpha = 0.0, weight = 0.0;
    Tangential anchor;
  };

 private:
  struct Sweep;
  template <class OnLevel>
  Sweep sweep(const NormalLaw& law, const SpringBedConfig& cfg, double a2, const Tangential& b2,
              OnLevel on_level) const;
  double spacing_for(const SpringBedConfig& cfg, double a2) const;
  void coarsen(const NormalLaw& law);
  /// Coarsens until L levels of spacing h reach a2.
  void cover(const NormalLaw& law, const SpringBedConfig& cfg, double a2);

  double a_ = 0.0, h_ = 0.0;  ///< h = 0: never in contact yet, the spacing is chosen at the first contact
  Tangential b_ = Tangential::zero(2), atom_anchor_ = Tangential::zero(2);
  std::vector<Level> levels_;  ///< the levels in contact, j = 0, 1, ... (α_j < a)
};

}  // namespace vibrotherm::contact

// Method of Memory Diagrams (MMD) for one contact cell (PHYSICS.md §3.3–3.4).
//
// State: the accumulated full-slip offset b0 and the memory diagram f on [0, a],
// a continuous piecewise-linear function with f(0) = 0, f(a) = b̃ = b − b0 and
// slopes in [−θμ, θμ], stored as breakpoints. The diagram is an exact bed of
// spring-sliders indexed by the approach α at which each came into contact
// (normal stiffness density N''(α), plus N'(0+) at α = 0); f(α) + b0 is the
// anchor of spring α, and spring α slips when |b̃ − f(α)| reaches θμ(a − α).
//
// Tractions: N = N(a); T = (1/θ) Σ_k m_k [N(α_{k+1}) − N(α_k)] (m_k: slopes).
//
// A step from the committed (a1, b1) to (a2, b2) follows the straight path
// between them. The new diagram is the old one clipped to the new wedge (exact
// for that path), and the dissipated energy ΔW is the friction work of every
// spring that slips on the path, integrated in closed form:
//   ΔW = 2μ Σ_springs r ∫_{τ(α)}^{e(α)} (a(t) − α) dt dN'(α),
// r the rate at which the pushing wedge edge moves, τ(α) when it reaches the
// spring, e(α) = min(1, detachment time). So ΔW is exact for the path, not a
// first- or second-order estimate, and ΔW >= 0 always. Trial evaluations are
// const: the wave solver evaluates at stages and commits once per step.
#pragma once

#include <cstddef>
#include <vector>

#include "vibrotherm/contact/normal_law.hpp"
#include "vibrotherm/contact/tangential.hpp"

namespace vibrotherm::contact {

enum class ContactState { Loss, Slide, Partial, Stick };

/// "loss" | "slide" | "partial" | "stick" (stick: in contact, nothing slipped).
const char* to_string(ContactState state);

struct Traction {
  double N = 0.0;  ///< normal traction, compressive positive [Pa]
  Tangential T;    ///< tangential traction [Pa], as many components as b
};

struct StepResult {
  double N = 0.0;
  Tangential T;
  double dW = 0.0;  ///< energy dissipated in the step [J/m²], >= 0
  ContactState state = ContactState::Loss;
};

struct MmdConfig {
  double mu = 1.0;                   ///< friction coefficient
  double theta = 1.0;                ///< Mindlin's θ = (2 − ν)/(2(1 − ν))
  double rel_tol = 1e-9;             ///< segments shorter than rel_tol·a are merged
  std::size_t max_breakpoints = 1024;  ///< hard bound on the stored diagram
};

class MemoryDiagram {
 public:
  /// Virgin state at (a, b): if a > 0, a flat diagram (everything stuck at b).
  void reset(const NormalLaw& law, double a, double b);

  /// Tractions at (a, b) from the committed state; the state is unchanged.
  Traction trial(const NormalLaw& law, const MmdConfig& cfg, double a, double b) const;

  /// Advances the committed state to (a, b) and returns tractions and ΔW.
  StepResult commit(const NormalLaw& law, const MmdConfig& cfg, double a, double b);

  /// Stored interface energy U = 2M(a) + (1/θ)∫ v² dN' [J/m²] (work units of the
  /// full relative displacement; v = b̃ − f is the elastic tangential part).
  double stored_energy(const MmdConfig& cfg) const;

  double a() const { return a_; }
  double b() const { return b_; }
  double b0() const { return b0_; }
  std::size_t breakpoints() const { return pts_.size(); }

  /// A breakpoint with the law values cached at α (no pow() in the hot path).
  struct Breakpoint {
    double alpha, f;     ///< abscissa and diagram value
    NormalLawValue law;  ///< N, N', M at alpha
    double T_before;     ///< (1/θ) Σ slopes·ΔN of the segments left of this point
  };
  const std::vector<Breakpoint>& diagram() const { return pts_; }
  /// The committed state as numbers (a, b, b0, then 6 per breakpoint) and back, bit for bit (checkpoints).
  std::vector<double> save() const;
  void restore(const double* values, std::size_t n);  ///< throws std::runtime_error on a malformed state

 private:
  void push_point(const NormalLaw& law, const MmdConfig& cfg, double alpha, double f, const NormalLawValue* value);
  void enforce_memory_bound(const MmdConfig& cfg);

  std::vector<Breakpoint> pts_;  ///< empty: contact lost
  double a_ = 0.0, b_ = 0.0, b0_ = 0.0;
};

}  // namespace vibrotherm::contact

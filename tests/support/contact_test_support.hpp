// Helpers for the contact unit tests: drive a crack law along a history and
// account the energies independently of the law.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact::testing {

inline ContactParameters hertz_params(double mu = 0.5, double nu = 0.3) {
  ContactParameters p;
  p.mu = mu;
  p.nu = nu;
  p.normal_law = "power";
  p.power_C = 1e18;
  p.power_p = 1.5;
  return p;
}

/// `crack_law` on the linear normal law N = 1e14 a, μ = 0.5.
inline ContactParameters on_linear_normal_law(const char* crack_law) {
  ContactParameters p;
  p.crack_law = crack_law;
  p.normal_law = "linear";
  p.linear_k = 1e14;
  p.mu = 0.5;
  return p;
}

/// Energy bookkeeping of one cell along a discretised path.
struct PathEnergy {
  double dissipated = 0.0;  ///< Σ ΔW
  double work_trap = 0.0;   ///< Σ (T_n + T_{n+1})Δb + (N_n + N_{n+1})Δa  (external work, trapezoid)
  double loop_area = 0.0;   ///< Σ (T_n + T_{n+1})Δb   (∮ 2T db over a closed cycle)
  double work_abs = 0.0;    ///< Σ |increments of work_trap|: the scale of the energies exchanged
};

/// A path point (a, b) as a function of the normalised time s in [0, 1].
using Path = std::function<void(double s, double& a, double& b)>;

/// Commits `steps` steps of path on [s0, s1] to cell 0 of law; the cell must
/// already sit at path(s0).
inline PathEnergy drive(CrackLaw& law, const Path& path, double s0, double s1, int steps,
                        StepResult* last = nullptr) {
  PathEnergy e;
  double a_prev, b_prev;
  path(s0, a_prev, b_prev);
  Traction prev = law.trial(0, a_prev, Tangential(b_prev));
  for (int k = 1; k <= steps; ++k) {
    double a, b;
    path(s0 + (s1 - s0) * k / steps, a, b);
    const StepResult r = law.commit(0, a, Tangential(b));
    e.dissipated += r.dW;
    e.loop_area += (prev.T[0] + r.T[0]) * (b - b_prev);
    const double dwork = (prev.T[0] + r.T[0]) * (b - b_prev) + (prev.N + r.N) * (a - a_prev);
    e.work_trap += dwork;
    e.work_abs += std::abs(dwork);
    prev = {r.N, r.T};
    a_prev = a;
    b_prev = b;
    if (last) *last = r;
  }
  return e;
}

/// Creates a one-cell law in its virgin state at (a, b), b with 1 or 2 components.
inline std::unique_ptr<CrackLaw> one_cell(const ContactParameters& p, double a, const Tangential& b) {
  auto law = create_crack_law(p);
  law->initialize(1, &a, &b);
  return law;
}
inline std::unique_ptr<CrackLaw> one_cell(const ContactParameters& p, double a, double b) {
  return one_cell(p, a, Tangential(b));
}

/// Work 2∫T·db of the step b1 → b2 on the path radial return solves exactly
/// (PHYSICS.md §3.5): elastic to p = b0 + ρ e/|e| (e = b2 − b0, ρ = μN/k_t),
/// then pulled radially to b2 at |T| = μN; a straight stick step if |e| ≤ ρ.
inline double dog_leg_work(const Tangential& b1, const Tangential& T1, const Tangential& b0, const Tangential& b2,
                    const Tangential& T2, double muN, double kt) {
  auto minus = [](const Tangential& x, const Tangential& y) { return Tangential(x[0] - y[0], x[1] - y[1]); };
  auto plus = [](const Tangential& x, const Tangential& y) { return Tangential(x[0] + y[0], x[1] + y[1]); };
  const Tangential e = minus(b2, b0);
  const double rho = muN / kt;
  if (!(norm(e) > rho)) return dot(plus(T1, T2), minus(b2, b1));
  const Tangential u = direction(e), p(b0[0] + rho * u[0], b0[1] + rho * u[1]), Tp(muN * u[0], muN * u[1]);
  return dot(plus(T1, Tp), minus(p, b1)) + 2.0 * muN * distance(b2, p);
}


/// A drifting ellipse of size ~ρ at step k (100 steps per turn): stick, slip,
/// reversals and rotation in one path.
inline Tangential drifting_ellipse(double rho, int k) {
  const double t = k / 100.0;
  return Tangential(rho * (1.5 * std::cos(2 * M_PI * t) + 0.3 * t), rho * 0.8 * std::sin(2 * M_PI * 1.3 * t));
}

/// Drives cell 0 of a Jenkins-like law (limit μN, stiffness kt; it sits at the
/// ellipse's step 0) 500 steps along drifting_ellipse at constant a: the largest
/// |ΔU + ΔW − dog-leg work| of a step over μNρ, and the total dissipated.
inline double worst_dog_leg_imbalance(CrackLaw& law, double a, double muN, double kt, double* dissipated) {
  const double rho = muN / kt;
  Tangential b1 = drifting_ellipse(rho, 0), T1 = law.trial(0, a, b1).T;
  double worst = 0.0;
  *dissipated = 0.0;
  for (int k = 1; k <= 500; ++k) {
    const Tangential b2 = drifting_ellipse(rho, k), b0 = law.slip_offset(0);
    const double U1 = law.stored_energy(0);
    const StepResult r = law.commit(0, a, b2);
    const double work = dog_leg_work(b1, T1, b0, b2, r.T, muN, kt);
    worst = std::max(worst, std::abs(law.stored_energy(0) - U1 + r.dW - work) / (muN * rho));
    *dissipated += r.dW;
    b1 = b2, T1 = r.T;
  }
  return worst;
}

}  // namespace vibrotherm::contact::testing

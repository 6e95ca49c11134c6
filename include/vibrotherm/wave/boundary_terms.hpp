// The boundary terms of the wave problem as objects: each kind of edge
// (absorbing dashpots, prescribed components, a traction load) says what it
// does to the acceleration of an explicit step, to the force and Jacobian of an
// implicit one, to the state after a step, and to the energy budget. The wave
// solver applies them in order and knows no kind by name: a new boundary kind
// (a PML, a Robin edge) is a new BoundaryTerm, not an edit of the solver.
#pragma once

#include <petscmat.h>

#include <memory>
#include <vector>

#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/wave_boundary.hpp"

namespace vibrotherm::wave {

/// The source signal g and its time derivatives at one time.
struct SignalValues {
  double g = 0, dg = 0, ddg = 0;
  static SignalValues At(const SourceTimeFunction& signal, double t);
};

/// Owned arrays (2 dofs per node) a term sees at a force evaluation.
struct ForceState {
  SignalValues signal;
  const PetscScalar* mass = nullptr;      ///< lumped mass per dof
  const PetscScalar* velocity = nullptr;
  double kick_dt = 0.0;  ///< > 0: a velocity-Verlet kick of this length (dashpots act on its mean velocity)
  /// Material damping C = αM on the kick's mean velocity makes every node's mass m (1 + α kick_dt/2)
  /// for the terms that solve for the kick's acceleration (dashpots) or read a support force.
  double mass_factor = 1.0;
};

/// What a term sees after an accepted step from t − h to t.
struct StepState {
  SignalValues start, middle, end;        ///< the signal at t − h, t − h/2, t
  double h = 0.0;
  const PetscScalar* u = nullptr;
  const PetscScalar* v = nullptr;
  bool reactions_from_kick = false;  ///< the support forces of the last Accelerate are the kick's
};

/// Energy a boundary exchanges with the waves, this rank's share [J/m in 2D, J in 3D].
struct BoundaryEnergy {
  double radiated = 0.0, work_source = 0.0;
  double damped = 0.0;  ///< dissipated by material damping (material_damping.hpp)
};

class BoundaryTerm {
 public:
  virtual ~BoundaryTerm() = default;
  /// acc: the acceleration of the interior forces, turned into the one with this
  /// term (terms run in order; a constraint last overrides its components).
  virtual void Accelerate(const ForceState& s, PetscScalar* acc) = 0;
  /// f += this term's force (implicit types' residual, no mass scaling).
  virtual void AddForce(const ForceState&, PetscScalar*) const {}
  /// Residual rows a constraint replaces: m (A·d − g̈) along d (implicit types).
  virtual void ConstrainResidual(const ForceState&, const PetscScalar* /*acc*/, PetscScalar* /*r*/) const {}
  /// J += the term's block (before assembly), rows numbered from rstart.
  virtual PetscErrorCode AddJacobian(PetscReal /*shift_v*/, PetscInt /*rstart*/, Mat /*J*/) const { return 0; }
  /// Constrained rows of an assembled J: m·shift_a on the diagonal, zero elsewhere.
  virtual PetscErrorCode ConstrainJacobian(PetscReal /*shift_a*/, PetscInt /*rstart*/, const PetscScalar* /*mass*/,
                                           Mat /*J*/) const {
    return 0;
  }
  /// After an accepted step: the exact prescribed values at the new time.
  virtual void Impose(const SignalValues&, PetscScalar* /*u*/, PetscScalar* /*v*/) const {}
  /// True when Account needs the support forces of the end state (a fresh Accelerate).
  virtual bool needs_end_state_forces() const { return false; }
  /// Adds the energy this term exchanged over the step.
  virtual void Account(const StepState& s, BoundaryEnergy* e) = 0;
  /// Restarting from a checkpoint: what Account remembers of the last step that
  /// the state cannot tell (this rank's numbers; restored before Resume) ...
  virtual std::vector<double> SavedAccount() const { return {}; }
  virtual void RestoreAccount(const std::vector<double>& /*values*/) {}
  /// ... and what it can: the last step's end state is the state restored (s.u, s.v).
  virtual void Resume(const StepState& /*s*/) {}
  /// The energy this term takes from each owned dof (material damping: its heat), kept from now on
  /// (false: the term keeps none) ...
  virtual bool KeepDofEnergy() { return false; }
  /// ... added to e (owned dofs) and forgotten: what was taken since the last call.
  virtual void TakeDofEnergy(PetscScalar* /*e*/) {}
};

/// Material damping C = αM on every dof (material_damping.cpp): first of the terms, on the
/// kick's mean velocity (unconditionally stable); accounted as `damped` unless `account` is
/// false (local time stepping accounts it kick by kick). `mass`: lumped, global.
PetscErrorCode CreateMaterialDamping(double rate, Vec mass, bool account, std::unique_ptr<BoundaryTerm>* term);

/// The kick's acceleration with damping rate α: m a = F − α m (v + kick a/2).
inline double DampedAcceleration(double interior, double v, double rate, double kick) {
  return (interior - rate * v) / (1.0 + 0.5 * rate * kick);
}

/// The terms of a boundary, in the order they act: traction load, dashpots, constraints.
/// `mass`: the lumped mass (global vector); `displacement_source`: the source prescribes.
PetscErrorCode CreateBoundaryTerms(const WaveBoundary& boundary, Vec mass, bool displacement_source,
                                   std::vector<std::unique_ptr<BoundaryTerm>>* terms);

}  // namespace vibrotherm::wave

// Clustered local time stepping (LTS) for the explicit wave step: a multi-rate
// velocity Verlet (impulse / r-RESPA form), one macro step H at a time.
//
// The stiffness is split by cell level (lts_levels.hpp): K = Σ_l K_l, each a
// symmetric matrix of its cells, so each level's force is conservative. Level l
// steps h_l = H / 2^l by kick–drift–kick, its two half kicks enclosing the two
// substeps of level l + 1:
//   Advance(l, t, h):  v += h/2 a_l            (rows of level-l cells)
//                      u += h v                (dofs whose finest cell is level l)
//                      Advance(l+1, t, h/2); Advance(l+1, t+h/2, h/2)
//                      a_l = A_l u;  v += h/2 a_l
// A level's force is evaluated once per substep (its end force is the next
// start force). Dofs move only at the rate of the finest level touching them,
// so every product reads positions at its own time, on every rank.
//
// The crack contact is a force of its own level Lc (its dofs drift at that
// rate): the coarsest level at least as fine as the crack's cells whose step
// satisfies the contact's stiffness; after each contact substep the contact's
// stiffness is checked (a Weyl bound, one scalar reduction) and the contact
// moves to finer levels when it stiffens: only its dofs pay for a stiff law.
//
// Boundary terms act in the kicks of the level their nodes drift with; the
// prescribed components are re-imposed after each drift of theirs.
// Stability: each level at -wave_lts_cfl of its own limit (SLEPc on M⁻¹K_l);
// the impulse form has resonances near its own limit, hence 0.7 by default.
#pragma once

#include <petscvec.h>

#include <memory>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/block_kernel.hpp"
#include "vibrotherm/wave/boundary_terms.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/lts_levels.hpp"
#include "vibrotherm/wave/material.hpp"
#include "vibrotherm/wave/wave_boundary.hpp"

namespace vibrotherm::wave {

class WaveInterface;

/// Cells, dofs and the spectrum of one level (for summaries).
struct LtsLevelInfo {
  PetscInt cells = 0, dofs = 0;  ///< global: cells of the level, dofs drifting at its rate
  double omega = 0.0;            ///< √λ_max(M⁻¹K_l)
};

class LtsStepper {
 public:
  LtsStepper();
  LtsStepper(const LtsStepper&) = delete;
  LtsStepper& operator=(const LtsStepper&) = delete;
  ~LtsStepper();

  /// Per-level operators, dof classes and boundary terms; the macro step from
  /// each level's spectrum (collective).
  PetscErrorCode Setup(const fe::LagrangeSpace& space, const ElasticMaterial& material, Vec mass,
                       const LtsLevels& levels, const WaveBoundary& boundary, const Excitation& excitation,
                       double omega_dt_max, const LtsOptions& options);
  /// The crack contact as a force of its own level (initial stiffness omega2).
  PetscErrorCode SetContact(WaveInterface* contact, double omega2);
  /// The level forces at the state (u at time t): before the first step and after a restore.
  PetscErrorCode Start(Vec u);
  /// One macro step from t of length h (≤ macro_step()): u, v in place.
  PetscErrorCode Step(double t, double h, Vec u, Vec v);
  /// The interior acceleration (all levels and the contact) at the state of the last Start/Step.
  PetscErrorCode InteriorAcceleration(Vec a) const;
  /// −Σ_l (h_l²/8) |K_l u|²_{M⁻¹}: the leading integrator term of the multi-rate step (global).
  PetscErrorCode IntegratorTerm(Vec u, double* term) const;

  double macro_step() const { return H_; }
  PetscInt levels() const { return static_cast<PetscInt>(level_.size()); }
  PetscInt contact_level() const { return contact_level_; }
  /// Prints the levels (steps, cells, dofs, the contact's) to stdout of rank 0. Collective.
  PetscErrorCode View(MPI_Comm comm) const;
  /// Times the contact moved to a finer level while stepping.
  PetscInt contact_refinements() const { return refinements_; }
  /// This rank's energy dissipated by material damping (exact per kick: c α Σ m v̄²).
  double damped() const { return damped_; }
  void set_damped(double damped) { damped_ = damped; }
  /// The contact's level and moves (a restored checkpoint); call Start after.
  PetscErrorCode set_contact_state(PetscInt level, PetscInt refinements, double macro_step, PetscInt halvings);
  /// Between macro steps: a contact more than one level finer than the crack's
  /// cells halves H instead (every level twice as fast, the contact back to one
  /// level below the crack's cells). *halved: whether H changed.
  PetscErrorCode TakeHalvings(bool* halved);
  PetscInt halvings() const { return halvings_; }
  bool halving_due() const { return contact_level_ > crack_level_ + 1 && pending_level_ < 0; }
  const std::vector<LtsLevelInfo>& info() const { return info_; }
  /// Work of one macro step over the work of global steps at the finest step: the speed-up bound.
  double speedup_bound() const;

 private:
  struct Level;
  PetscErrorCode SetupLevel(PetscInt l, const fe::LagrangeSpace& space, const ElasticMaterial& material,
                            const LtsLevels& levels, const std::vector<char>& touched);
  PetscErrorCode SetupClasses(const std::vector<PetscInt>& finest);
  PetscErrorCode SetupBoundary(const WaveBoundary& boundary);
  PetscErrorCode Advance(PetscInt l, double t, double h, Vec u, Vec v);
  PetscErrorCode Force(PetscInt l, double t, double h, Vec u);
  PetscErrorCode Kick(PetscInt l, double t, double c, Vec v);
  PetscErrorCode Drift(PetscInt l, double t, double h, Vec u, Vec v);
  PetscErrorCode RefineContact(double omega2, double t);
  PetscErrorCode MoveContact(Vec u);
  PetscErrorCode ForceWithoutCommit(PetscInt l, Vec u);
  PetscErrorCode AddLevel();
  /// The first level from `from` on (added as needed) whose step holds the
  /// level's stiffness plus a contact of squared frequency omega2.
  PetscErrorCode StableLevel(PetscInt from, double omega2, PetscInt* level);
  /// Drops the contact-only levels finer than contact_level.
  void TrimLevels(PetscInt contact_level);
  PetscErrorCode AssignContactDofs();
  double Limit() const { return cfl_ * omega_dt_max_; }

  std::vector<std::unique_ptr<Level>> level_;
  std::vector<LtsLevelInfo> info_;
  std::vector<PetscInt> element_finest_;  ///< per owned dof: finest level of its cells
  std::vector<PetscInt> contact_dofs_;    ///< owned dofs the contact acts on
  std::vector<PetscInt> dof_level_;       ///< per owned dof: the level whose rate it moves at
  Vec mass_ = nullptr, scratch_ = nullptr;  ///< mass: not owned
  Vec work_ = nullptr;                      ///< IntegratorTerm's second vector
  Excitation excitation_;
  WaveInterface* contact_ = nullptr;
  PetscInt element_levels_ = 1, contact_level_ = -1, refinements_ = 0;
  PetscInt components_ = 2;  ///< dofs per node (the space's components)
  PetscInt pending_level_ = -1;
  PetscInt crack_level_ = 0;   ///< finest level of the crack's cells
  PetscInt halvings_ = 0;      ///< times H was halved for the contact  ///< the contact's next level, moved to after the current kick
  double H_ = 0.0, omega_dt_max_ = 2.0, cfl_ = 0.7;
  double damping_rate_ = 0.0;  ///< material damping α (C = αM), applied in every kick
  double damped_ = 0.0;        ///< this rank's energy dissipated by it, kick by kick
  MPI_Comm comm_ = MPI_COMM_NULL;
};

}  // namespace vibrotherm::wave

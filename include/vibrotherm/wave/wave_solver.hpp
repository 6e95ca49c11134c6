// Elastodynamics on the crack-split mesh (plane strain in 2D, or 3D: the dimension is the
// DM's), integrated by one PETSc TS (options prefix -wave_):
//   u̇ = v, M v̇ = −K u − C v + f_source(t) + f_extra(u),
// K, M and A = −M⁻¹K from the operator (wave_operator.hpp), which knows nothing of time.
//
// State X = [u; v] (per rank: owned u block, then owned v block). Explicit
// default: velocity Verlet (drift–kick–drift; verlet_ts.hpp, or basicsymplectic type 2), with the
// split RHS; inside the kick the dashpot force uses the trapezoidal mean of the
// velocity (implicit in the 2x2 dashpot blocks), so absorbing edges never limit
// the step. Other types (rk, ssp, alpha2-free explicit ones) use the full RHS.
// Boundary terms (boundary_terms.hpp: dashpots, prescribed components, traction
// load) act in order on the acceleration; prescribed components are reset
// exactly after each step. The step: step_control.hpp. History-dependent forces
// (the crack interface) plug in through WaveInterface; a bulk force affine in u
// (the two-way thermal stress) through BodyForce (body_force.hpp, wave_body_force.cpp).
// Files: wave_solver.cpp (setup, TS, explicit stepping), wave_alpha2.cpp
// (implicit alpha2), wave_lts.cpp (local time stepping), wave_energy.cpp (energy
// accounting), wave_body_force.cpp, wave_solver_state.cpp (checkpoints).
#pragma once

#include <petscts.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/mesh/plex/point_origin.hpp"
#include "vibrotherm/wave/body_force.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"
#include "vibrotherm/wave/block_kernel.hpp"
#include "vibrotherm/wave/boundary_terms.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/lts_stepper.hpp"
#include "vibrotherm/wave/material.hpp"
#include "vibrotherm/wave/step_control.hpp"
#include "vibrotherm/wave/wave_boundary.hpp"
#include "vibrotherm/wave/wave_operator.hpp"

namespace vibrotherm::wave {

/// How the harmonic start solves its doubled system: MUMPS when its factor fits the memory
/// limit, else GMRES (auto); always MUMPS (direct); always GMRES with multigrid (krylov).
enum class HarmonicSolver { kAuto, kDirect, kKrylov };

/// How the waves begin: at rest (the source switches on), in the steady response of the
/// linearized waves (harmonic_start.cpp), or in a state an earlier run saved at a period
/// boundary of its steady state (-periodic_save_state), scaled to this run's source amplitude:
/// a warm start, for runs of one scene at one frequency and neighbouring amplitudes.
enum class WaveStart { kRest, kHarmonic, kState };

struct WaveOptions {
  PetscInt degree = 2;   ///< -wave_degree 1|2 (Q2/P2 by default: Q1 is 32 % off in dissipated energy on the paper mesh)
  double cfl = 0.9;      ///< -wave_cfl: fraction of the stability limit
  double dt = 0.0;       ///< -wave_dt: explicit step (0: cfl × limit)
  ContactStepRule contact_step = ContactStepRule::kCurrent;  ///< -wave_contact_step current|worst_case
  StiffnessKernel kernel = StiffnessKernel::kBlocked;        ///< -wave_kernel petsc|blocked
  LtsOptions lts;  ///< -wave_lts on|off, -wave_lts_max_levels, -wave_lts_cfl, -wave_lts_wiggle
  /// -wave_start rest|harmonic|state: the waves' initial state; unless rest, the source's switch-on is skipped.
  WaveStart start = WaveStart::kRest;
  std::string start_state;  ///< -wave_start_state FILE: the saved state -wave_start state begins in
  /// -wave_harmonic_memory_limit [GB]: what the harmonic start's MUMPS factorisation may take
  /// (0: 0.9 x the memory available; -force: factor even above it).
  double harmonic_memory_limit_gb = 0.0;
  bool harmonic_force = false;  ///< -force (declared with the mesh, MeshSource; set by ReadScene): factor above the limit
  /// -wave_harmonic_solver auto|direct|krylov (harmonic_krylov.hpp).
  HarmonicSolver harmonic_solver = HarmonicSolver::kAuto;
  /// Every step divides this (0: any step): the heat step of a periodic source (-periodic on),
  /// so that source periods end on wave steps (set by the scene, not an option).
  double step_quantum = 0.0;
};
/// The -wave_* options, declared (option_spec.hpp).
const std::vector<OptionSpec<WaveOptions>>& WaveOptionSpecs();
PetscErrorCode ReadWaveOptions(MPI_Comm comm, WaveOptions* options, OptionValues* values = nullptr);

/// Forces the wave solver does not own (the crack interface): evaluated as a
/// pure function of u at every force evaluation, committed once per accepted step.
class WaveInterface {
 public:
  virtual ~WaveInterface() = default;
  /// a += M⁻¹ f(u): trial forces from the committed history.
  virtual PetscErrorCode AddAcceleration(Vec u, Vec a) = 0;
  /// Advances the history to u after an accepted step of size dt.
  virtual PetscErrorCode Commit(Vec u, double dt) = 0;
  /// Takes u as its committed state without counting the way there as dissipated (the warm
  /// start: that history built the saved state, it is no heat of this run).
  virtual PetscErrorCode StartIn(Vec u) = 0;
  /// Largest ω² the interface adds to M⁻¹K at its current state, or with every
  /// cell pressed `extra_approach` beyond its initial approach (for the initial step).
  virtual PetscErrorCode MaxFrequencySquared(double* omega2, double extra_approach = -1.0) = 0;
  /// marker[i] = 1 on the owned dofs its forces act on (local time stepping moves them at the contact's rate).
  virtual PetscErrorCode MarkDofs(Vec marker) = 0;
  /// Energy stored in the interface and dissipated so far [J/m in 2D, J in 3D] (global).
  virtual PetscErrorCode Energies(double* stored, double* dissipated) = 0;
  /// The harmonic start (harmonic_start.cpp): the entries (global dof row, column, value) of the
  /// interface's tangent stiffness at its committed state (this rank's cells) ...
  virtual PetscErrorCode TangentStiffness(std::vector<PetscInt>* rows, std::vector<PetscInt>* cols,
                                          std::vector<double>* values) const = 0;
};

/// Energies of the wave field: J per metre of depth in 2D (plane strain), J in 3D. For velocity Verlet the
/// exactly conserved discrete energy of the linear system is
///   KE + SE − (dt²/8) vᵀKv
/// (drift–kick–drift; derived in the note of issue 4): `integrator` holds the
/// last term, so that budgets close to rounding, not to O((ω dt)²).
struct WaveEnergy {
  double kinetic = 0, strain = 0, radiated = 0, work_source = 0, integrator = 0;
  double interface_stored = 0, dissipated = 0;  ///< from the WaveInterface, if any
  double work_body = 0;  ///< work of the BodyForce on the waves, if any (two-way thermal stress)
  double damped = 0;     ///< dissipated by material damping (-material_loss_factor)
};

class WaveSolver {
 public:
  WaveSolver() = default;
  WaveSolver(const WaveSolver&) = delete;
  WaveSolver& operator=(const WaveSolver&) = delete;
  ~WaveSolver();

  PetscErrorCode Setup(DM dm, const ElasticMaterial& material, const Excitation& excitation,
                       const WaveOptions& options);
  /// Advances by n steps of the constant step dt. Couplings and outputs run on
  /// this grid: velocity Verlet is stable and conservative only with a constant
  /// step (periodically shortened steps were measured to excite an instability).
  PetscErrorCode AdvanceSteps(PetscInt n);
  /// Advances to exactly t_end: whole steps, then one shortened step. For the
  /// end of a run or of a test, not for repeated use.
  PetscErrorCode AdvanceTo(double t_end);
  /// Steps of size dt that fit before t_end.
  PetscInt StepsUntil(double t_end) const;

  /// Attaches an interface (not owned); call after Setup. The initial step
  /// includes its stiffness as the -wave_contact_step rule says (now, or at the
  /// worst case a0 + worst_approach); the check after every step shrinks it when
  /// the contact stiffens beyond that (see step_control.hpp).
  PetscErrorCode SetInterface(WaveInterface* interface, double worst_approach);
  /// Attaches a body force (not owned; null detaches); its stiffness bound enters the step.
  PetscErrorCode SetBodyForce(BodyForce* force);

  /// Called after every accepted step (probes, outputs, coupling).
  std::function<PetscErrorCode(const WaveSolver&)> on_step;

  PetscErrorCode Energy(WaveEnergy* e) const;  ///< kinetic and strain computed now
  double time() const { return time_; }
  PetscInt steps() const { return steps_; }
  /// The step and its rule: dt(), stable_dt(), implicit() (step_control.hpp).
  const StepControl& step() const { return step_; }
  double omega_max() const { return omega_max_; }
  PetscInt dt_reductions() const { return lts_active_ ? lts_.contact_refinements() : step_.reductions(); }
  /// -wave_start harmonic: u, v at t = 0 the steady response to the source at its frequency, with the
  /// interface linearized at its initial state (harmonic_start.cpp). After SetInterface. Collective.
  PetscErrorCode StartHarmonic();
  /// The warm start: u and v of a saved state (Save's keyed "wave/u", "wave/v") times `scale`,
  /// booked as the source's work as the harmonic start's state is. After SetInterface. Collective.
  PetscErrorCode StartFromState(const store::Checkpoint& state, const mesh::PointOrigin& origin, double scale);
  /// Local time stepping: its levels when it runs (null when not), and why not when asked for but off.
  const LtsStepper* lts() const { return lts_active_ ? &lts_ : nullptr; }
  const std::string& lts_note() const { return lts_note_; }
  /// The elastic operator the integrators step with: K, M, A = −M⁻¹K (wave_operator.hpp).
  const WaveOperator& op() const { return op_; }
  const fe::LagrangeSpace& space() const { return op_.space(); }
  /// The material damping's energy per dof kept from now on (the damping heat); kept: false when
  /// there is no damping term or it is accounted elsewhere (local time stepping) ...
  PetscErrorCode KeepDampingEnergy(bool* kept);
  /// ... and into e (a global vector of the DM): what it took since the last call.
  PetscErrorCode TakeDampingEnergy(Vec e);
  /// Displacement and velocity (global vectors of the DM; views on the state's
  /// memory, valid until RestoreFields; writes through them change the state).
  PetscErrorCode GetFields(Vec* u, Vec* v) const;
  PetscErrorCode RestoreFields(Vec* u, Vec* v) const;
  /// The state between steps (u, v keyed by dof origin; time, steps, step
  /// control, energy accounts) into a checkpoint, and back (wave_solver_state.cpp).
  /// Restore after Setup and SetInterface; the interface restores itself.
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin);
  /// What grows with time rather than repeating in a periodic state (this rank's: the clock,
  /// radiated, source work, body work, damped), for the periodic continuation ...
  std::vector<double> Accumulated() const;
  /// ... which jumps ahead by adding increments of these (after restoring a stored state).
  PetscErrorCode JumpAhead(const std::vector<double>& increments);

 private:
  // Explicit types (wave_solver.cpp).
  static PetscErrorCode RHSFull(TS ts, PetscReal t, Vec X, Vec F, void* ctx);
  static PetscErrorCode RHSPosition(TS ts, PetscReal t, Vec v, Vec f, void* ctx);
  static PetscErrorCode RHSMomentum(TS ts, PetscReal t, Vec u, Vec f, void* ctx);
  static PetscErrorCode PostStep(TS ts);
  PetscErrorCode CreateFieldViews(MPI_Comm comm, PetscInt n);
  PetscErrorCode CreateTS(MPI_Comm comm);
  PetscErrorCode SetupStepControl(MPI_Comm comm);
  PetscErrorCode CheckFinite(double t, double h) const;
  /// a = M⁻¹(−K u − C v + f(t)) with constraints; kick_dt > 0: trapezoidal dashpot over a kick.
  PetscErrorCode Acceleration(double t, Vec u, Vec v, Vec a, double kick_dt);
  /// After a step: the contact's stability check; a changed step keeps the energy budget continuous.
  PetscErrorCode CheckStableStep();
  // Local time stepping (wave_lts.cpp).
  PetscErrorCode SetupLts();
  static PetscErrorCode MacroStep(void* ctx, PetscReal t, PetscReal h, Vec u, Vec v);
  PetscErrorCode CheckMacroStep();
  /// The boundary terms on an interior acceleration a (kick_dt as in Acceleration).
  PetscErrorCode ApplyTerms(double t, Vec v, Vec a, double kick_dt);
  // The harmonic start (harmonic_start.cpp: HarmonicStart solves it).
  /// The state's energy (the stuck springs' with it) as the source's work at t = 0.
  /// Books the initial state's energy as the source's work: the field's, and the interface's
  /// (`interface_energy`: its stuck springs for the harmonic start, its stored energy for a warm one).
  PetscErrorCode BookInitialEnergy(double interface_energy);
  /// ½ [u]ᵀ K_c [u] of the interface's springs stuck at its committed state.
  PetscErrorCode StuckSpringEnergy(double* springs);
  /// u and v from a checkpoint's keyed "wave/u", "wave/v", times scale (restart, warm start); the owned
  /// dofs' keys into *owned_keys if given.
  PetscErrorCode LoadFields(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin, double scale,
                            std::vector<long long>* owned_keys = nullptr);
  // Implicit alpha2 (wave_alpha2.cpp): M A + C V + K U = f(t), constraints on the acceleration.
  PetscErrorCode SetupAlpha2(MPI_Comm comm);
  static PetscErrorCode I2Function(TS ts, PetscReal t, Vec U, Vec V, Vec A, Vec F, void* ctx);
  static PetscErrorCode I2Jacobian(TS ts, PetscReal t, Vec U, Vec V, Vec A, PetscReal shiftV, PetscReal shiftA,
                                   Mat J, Mat P, void* ctx);
  /// f = −K u − C v + g(t) f_source (no mass scaling, no constraints).
  PetscErrorCode Forces(double t, Vec u, Vec v, Vec f) const;
  // Body force (wave_body_force.cpp): a += M⁻¹ f(t, u); its work f·Δu per step.
  PetscErrorCode AddBodyForce(double t, Vec u, Vec a);
  PetscErrorCode AccountBodyWork(double t, Vec u);
  // Energy accounting (wave_energy.cpp).
  PetscErrorCode AccountStep(double t, double h);
  /// −(dt²/8) vᵀKv: velocity Verlet's integrator term at the current step.
  PetscErrorCode IntegratorTerm(double dt, double* term) const;

  DM dm_ = nullptr;
  WaveOperator op_;
  ElasticMaterial material_;
  Excitation excitation_;
  WaveOptions options_;
  WaveBoundary boundary_;
  std::vector<std::unique_ptr<BoundaryTerm>> terms_;  ///< in the order they act
  StepControl step_;
  Vec X_ = nullptr, force_ = nullptr;
  Vec u_ = nullptr, v_ = nullptr;  ///< u and v: vectors on X_'s memory (GetFields)
  Vec u_view_ = nullptr, v_view_ = nullptr;  ///< alpha2: the TS's solution and velocity, views into X_
  Mat J_ = nullptr;                          ///< alpha2 Jacobian
  IS is_u_ = nullptr, is_v_ = nullptr;
  TS ts_ = nullptr;
  bool symplectic_ = false, trapezoidal_kick_ = false, velocity_verlet_ = false, second_order_ = false;
  double omega_max_ = 0, time_ = 0;
  WaveInterface* interface_ = nullptr;
  BodyForce* body_ = nullptr;
  Vec body_f_ = nullptr, body_u_ = nullptr, body_a_ = nullptr;  ///< last force (the kick's), u after the last step, work
  Vec body_f_end_ = nullptr;  ///< the force at the last step's end (types other than velocity Verlet)
  double body_work_ = 0.0;  ///< this rank's share of the body force's work so far
  PetscInt steps_ = 0;
  BoundaryEnergy accounted_;         ///< this rank's radiated energy and source work so far
  double integrator_offset_ = 0.0;   ///< integrator-term jumps of earlier step changes (global)
  bool reaction_from_kick_ = false;  ///< the constraints' support forces are the last kick's
  LtsStepper lts_;
  bool lts_active_ = false, lts_started_ = false;  ///< started: the level forces are those of the state
  std::string lts_note_;
};

}  // namespace vibrotherm::wave

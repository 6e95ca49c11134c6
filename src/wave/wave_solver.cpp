#include "vibrotherm/wave/wave_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vibrotherm/options/petsc/option_choice.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/wave/elastic_operator.hpp"
#include "vibrotherm/wave/stability.hpp"
#include "vibrotherm/wave/verlet_ts.hpp"

namespace vibrotherm::wave {

const std::vector<OptionSpec<WaveOptions>>& WaveOptionSpecs() {
  using O = WaveOptions;
  using L = LtsOptions;
  using contact::Range;
  static const std::vector<OptionSpec<O>> specs = {
      IntOption("-wave_degree", &O::degree, Range::between(1, 2), "Lagrange degree of the displacement"),
      RealOption("-wave_cfl", &O::cfl, Range::open_closed(0.0, 1.0), "",
                 "Time step as a fraction of the explicit stability limit"),
      RealOption("-wave_dt", &O::dt, Range::at_least(0.0), "s", "Time step (0: cfl x stability limit)"),
      ChoiceOption("-wave_contact_step", &O::contact_step, {"current", "worst_case"},
                   "Contact stiffness in the step: current (the contact as it is, shrunk when it stiffens) or "
                   "worst_case (every cell pressed twice the source amplitude)"),
      ChoiceOption("-wave_kernel", &O::kernel, {"petsc", "blocked"},
                   "Product with the stiffness in the explicit steps and energies: petsc (MatMult) or blocked (2x2-block "
                   "loop, same result to rounding)"),
      NestedOption(&O::lts, ChoiceOption("-wave_lts", &L::on, {"off", "on"},
                                         "Clustered local time stepping: cells step at rates 2^-l of the macro step by "
                                         "their own stability limit (on) or all at the smallest cell's step (off)")),
      ChoiceOption("-wave_start", &O::start, {"rest", "harmonic", "state"},
                   "Initial state: rest (the source switches on), harmonic (the steady response of the linearized "
                   "waves to the running source: a resonant specimen's build-up skipped), or state (-wave_start_state: "
                   "a steady state saved by a run at the same frequency, scaled to this run's amplitude)"),
      TextOption("-wave_start_state", &O::start_state,
                 "File of the state -wave_start state begins in (written by -periodic_save_state)"),
      RealOption("-wave_harmonic_memory_limit", &O::harmonic_memory_limit_gb, Range::at_least(0.0), "GB",
                 "Memory the harmonic start's MUMPS factorisation may take (0: 0.9 x available)"),
      ChoiceOption("-wave_harmonic_solver", &O::harmonic_solver, {"auto", "direct", "krylov"},
                   "The harmonic start's linear solve: auto (MUMPS if its factor fits the memory limit, else GMRES), "
                   "direct (MUMPS) or krylov (GMRES, multigrid on each part)"),
      NestedOption(&O::lts, IntOption("-wave_lts_max_levels", &L::max_levels, Range::between(1, 12),
                                      "Most levels of local time stepping (rate 2 each)")),
      NestedOption(&O::lts, RealOption("-wave_lts_cfl", &L::cfl, Range::open_closed(0.0, 1.0), "",
                                       "Each LTS level's step as a fraction of its own stability limit")),
      NestedOption(&O::lts, RealOption("-wave_lts_wiggle", &L::wiggle, Range::open_closed(0.5, 1.0), "",
                                       "LTS cluster boundaries: the finest step times this factor")),
  };
  return specs;
}

PetscErrorCode ReadWaveOptions(MPI_Comm comm, WaveOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Elastic waves", WaveOptionSpecs(), o, values));
  PetscFunctionReturn(0);
}

WaveSolver::~WaveSolver() {
  (void)TSDestroy(&ts_);
  if (u_view_) (void)VecRestoreSubVector(X_, is_u_, &u_view_);
  if (v_view_) (void)VecRestoreSubVector(X_, is_v_, &v_view_);
  (void)MatDestroy(&J_);
  for (Vec* v : {&u_, &v_, &X_, &force_, &body_f_, &body_u_, &body_a_, &body_f_end_}) (void)VecDestroy(v);
  (void)ISDestroy(&is_u_);
  (void)ISDestroy(&is_v_);
}

PetscErrorCode WaveSolver::Setup(DM dm, const ElasticMaterial& material, const Excitation& excitation,
                                 const WaveOptions& options) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  dm_ = dm;
  material_ = material;
  excitation_ = excitation;
  options_ = options;
  PetscCall(op_.Setup(dm, material, options.degree));
  PetscCall(BuildWaveBoundary(op_.space(), material, excitation, &boundary_));
  PetscCall(CreateBoundaryTerms(boundary_, op_.mass(), excitation.type == SourceType::Displacement, &terms_));

  PetscInt n, rstart;
  PetscCall(VecGetLocalSize(op_.mass(), &n));
  PetscCall(VecCreateMPI(comm, 2 * n, PETSC_DETERMINE, &X_));
  PetscCall(VecSet(X_, 0.0));
  PetscCall(VecGetOwnershipRange(X_, &rstart, nullptr));
  PetscCall(ISCreateStride(comm, n, rstart, 1, &is_u_));
  PetscCall(ISCreateStride(comm, n, rstart + n, 1, &is_v_));
  PetscCall(CreateFieldViews(comm, n));
  PetscCall(VecDuplicate(op_.mass(), &force_));
  PetscCall(CreateTS(comm));
  PetscCall(SetupStepControl(comm));
  PetscCall(SetupLts());
  if (material.damping_rate > 0.0) {  // first: the later terms see the damped mass; LTS accounts it per kick
    std::unique_ptr<BoundaryTerm> damping;
    PetscCall(CreateMaterialDamping(material.damping_rate, op_.mass(), !lts_active_, &damping));
    terms_.insert(terms_.begin(), std::move(damping));
  }
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  PetscCall(TSSetTime(ts_, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::CreateFieldViews(MPI_Comm comm, PetscInt n) {
  PetscFunctionBeginUser;
  // u and v as vectors on the state's own memory, made once: a VecGetSubVector
  // per use creates a vector (a layout set up by collectives) each time.
  PetscScalar* x;
  PetscCall(VecGetArray(X_, &x));
  PetscCall(VecCreateMPIWithArray(comm, 1, n, op_.dofs(), x, &u_));
  PetscCall(VecCreateMPIWithArray(comm, 1, n, op_.dofs(), x + n, &v_));
  PetscCall(VecRestoreArray(X_, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::CreateTS(MPI_Comm comm) {
  PetscFunctionBeginUser;
  PetscCall(TSCreate(comm, &ts_));
  PetscCall(TSSetOptionsPrefix(ts_, "wave_"));
  PetscCall(TSSetApplicationContext(ts_, this));
  PetscCall(TSSetProblemType(ts_, TS_NONLINEAR));
  PetscCall(RegisterVelocityVerletTS());
  PetscCall(TSSetType(ts_, kVelocityVerletTS));
  PetscCall(TSRHSSplitSetIS(ts_, "position", is_u_));
  PetscCall(TSRHSSplitSetIS(ts_, "momentum", is_v_));
  PetscCall(TSSetPostStep(ts_, PostStep));
  PetscCall(TSSetExactFinalTime(ts_, TS_EXACTFINALTIME_STEPOVER));  // Advance() lands on the end time itself
  TSAdapt adapt;
  PetscCall(TSGetAdapt(ts_, &adapt));
  PetscCall(TSAdaptSetType(adapt, TSADAPTNONE));  // fixed steps unless the options say otherwise
  PetscCall(TSSetFromOptions(ts_));
  TSType type;
  PetscCall(TSGetType(ts_, &type));
  const bool own_verlet = std::string(type) == kVelocityVerletTS;
  symplectic_ = std::string(type) == TSBASICSYMPLECTIC || own_verlet;
  second_order_ = std::string(type) == TSALPHA2;
  if (second_order_) {
    PetscCall(SetupAlpha2(comm));
  } else {
    // An RHS function would be subtracted from an implicit residual: only for explicit types.
    PetscCall(TSSetRHSFunction(ts_, nullptr, RHSFull, this));
    PetscCall(TSRHSSplitSetRHSFunction(ts_, "position", nullptr, RHSPosition, this));
    PetscCall(TSRHSSplitSetRHSFunction(ts_, "momentum", nullptr, RHSMomentum, this));
    PetscCall(VelocityVerletSetPositionRateIsMomentum(ts_, PETSC_TRUE));  // RHSPosition is u̇ = v
  }
  // Types 1 and 2 kick once per step with coefficient 1: the trapezoidal dashpot is exact there.
  std::string scheme = TSBASICSYMPLECTICVELVERLET;
  PetscCall(OptionText("wave_", "-ts_basicsymplectic_type", &scheme));
  trapezoidal_kick_ = own_verlet || (symplectic_ && (scheme == "1" || scheme == "2"));
  velocity_verlet_ = own_verlet || (symplectic_ && scheme == "2");
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::SetupStepControl(MPI_Comm comm) {
  PetscFunctionBeginUser;
  // Stable step: ω_max (SLEPc) and the measured (ω dt)_max of this TS type.
  double omega_dt_max;
  bool implicit;
  PetscCall(op_.LargestFrequency(&omega_max_));
  // alpha2 keeps K for its Jacobian, and multiplies by PETSc (the blocked kernel serves explicit types).
  PetscCall(op_.MakeStepping(second_order_, second_order_ ? StiffnessKernel::kPetsc : options_.kernel));
  TSType type;
  PetscCall(TSGetType(ts_, &type));
  PetscCall(OscillatorStabilityLimit("wave_", &omega_dt_max, &implicit));
  PetscCheck(implicit || omega_dt_max > 0.05, comm, PETSC_ERR_USER_INPUT,
             "-wave_ts_type %s is unstable for undamped waves (its stability region misses the imaginary axis); use "
             "basicsymplectic, rk with -wave_ts_rk_type 4, or ssp with -wave_ts_ssp_type rk104",
             type);
  PetscCall(step_.Setup(comm, omega_max_, implicit ? 0.0 : omega_dt_max, options_.cfl, options_.dt, type,
                        options_.step_quantum));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Acceleration(double t, Vec u, Vec v, Vec a, double kick_dt) {
  PetscFunctionBeginUser;
  PetscCall(op_.Apply(u, a));  // −M⁻¹K u
  if (interface_) PetscCall(interface_->AddAcceleration(u, a));
  if (body_) PetscCall(AddBodyForce(t, u, a));
  PetscCall(ApplyTerms(t, v, a, kick_dt));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::ApplyTerms(double t, Vec v, Vec a, double kick_dt) {
  PetscFunctionBeginUser;
  ForceState state;
  state.signal = SignalValues::At(excitation_.signal, t);
  state.kick_dt = kick_dt;
  state.mass_factor = 1.0 + 0.5 * material_.damping_rate * kick_dt;
  PetscScalar* acc;
  PetscCall(VecGetArray(a, &acc));
  PetscCall(VecGetArrayRead(v, &state.velocity));
  PetscCall(VecGetArrayRead(op_.mass(), &state.mass));
  for (auto& term : terms_) term->Accelerate(state, acc);
  PetscCall(VecRestoreArrayRead(op_.mass(), &state.mass));
  PetscCall(VecRestoreArrayRead(v, &state.velocity));
  PetscCall(VecRestoreArray(a, &acc));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::RHSFull(TS, PetscReal t, Vec X, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  Vec u, v, fu, fv;
  PetscCall(VecGetSubVector(X, self->is_u_, &u));
  PetscCall(VecGetSubVector(X, self->is_v_, &v));
  PetscCall(VecGetSubVector(F, self->is_u_, &fu));
  PetscCall(VecGetSubVector(F, self->is_v_, &fv));
  PetscCall(VecCopy(v, fu));
  PetscCall(self->Acceleration(t, u, v, fv, 0.0));
  PetscCall(VecRestoreSubVector(F, self->is_v_, &fv));
  PetscCall(VecRestoreSubVector(F, self->is_u_, &fu));
  PetscCall(VecRestoreSubVector(X, self->is_v_, &v));
  PetscCall(VecRestoreSubVector(X, self->is_u_, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::RHSPosition(TS, PetscReal, Vec v, Vec f, void*) { return VecCopy(v, f); }

PetscErrorCode WaveSolver::RHSMomentum(TS, PetscReal t, Vec u, Vec f, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  // The momentum function sees positions only; the velocity is the live part of
  // the state. The TS passed in is basicsymplectic's sub-TS: take the step from ours.
  PetscReal h;
  PetscCall(TSGetTimeStep(self->ts_, &h));
  PetscCall(self->Acceleration(t, u, self->v_, f, self->trapezoidal_kick_ ? h : 0.0));  // read only
  self->reaction_from_kick_ = self->trapezoidal_kick_;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::SetInterface(WaveInterface* interface, double worst_approach) {
  PetscFunctionBeginUser;
  PetscCheck(!second_order_, PetscObjectComm((PetscObject)dm_), PETSC_ERR_SUP,
             "-wave_ts_type alpha2 with a contact law is not supported yet: use an explicit type");
  interface_ = interface;
  // The initial step: the contact as it is now, or at its assumed worst case.
  double omega2;
  if (options_.contact_step == ContactStepRule::kWorstCase) PetscCall(interface_->MaxFrequencySquared(&omega2, worst_approach));
  else PetscCall(interface_->MaxFrequencySquared(&omega2));
  if (lts_active_) {  // the contact in a level of its own stiffness (H halved if it needs more)
    PetscCall(lts_.SetContact(interface_, omega2));
    step_.UseMacroStep(lts_.macro_step());
    PetscCall(TSSetTimeStep(ts_, step_.dt()));
    lts_started_ = false;
    PetscFunctionReturn(0);
  }
  step_.IncludeContact(omega2);
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  PetscCall(CheckStableStep());
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::CheckStableStep() {
  PetscFunctionBeginUser;
  if (!interface_ || step_.implicit()) PetscFunctionReturn(0);
  if (lts_active_) PetscFunctionReturn(CheckMacroStep());
  double omega2, before = step_.dt(), term_before = 0.0, term_after = 0.0;
  bool changed;
  PetscCall(interface_->MaxFrequencySquared(&omega2));
  const double q = step_.quantum(), k = q > 0.0 ? time_ / q : 0.0;
  PetscCall(step_.Check(omega2, time_, steps_, std::abs(k - std::round(k)) < 1e-6, &changed));
  if (!changed) PetscFunctionReturn(0);
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  // The conserved energy of velocity Verlet depends on the step: keep the budget continuous.
  PetscCall(IntegratorTerm(before, &term_before));
  PetscCall(IntegratorTerm(step_.dt(), &term_after));
  integrator_offset_ += term_before - term_after;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::CheckMacroStep() {
  PetscFunctionBeginUser;
  // The contact went more than one level below the crack's cells: H halves, the
  // integrator term (which depends on the steps) carried over.
  if (!lts_.halving_due()) PetscFunctionReturn(0);
  double before = 0.0, after = 0.0;
  PetscCall(IntegratorTerm(0.0, &before));
  const double H = lts_.macro_step();
  bool halved;
  PetscCall(lts_.TakeHalvings(&halved));
  if (!halved) PetscFunctionReturn(0);
  // The contact now acts in another level object, whose stored force lacks it: the
  // next macro step starts from the level forces of the state (as after a restart).
  lts_started_ = false;
  PetscCall(IntegratorTerm(0.0, &after));
  integrator_offset_ += before - after;
  if (lts_.halvings() == 1)
    PetscCall(PetscPrintf(PetscObjectComm((PetscObject)dm_),
                          "wave: the crack contact needs a step below half its cells' at t = %g s: macro step halved "
                          "from %g to %g s (every level pays; further halvings are counted in summary.json)\n",
                          time_, H, lts_.macro_step()));
  step_.UseMacroStep(lts_.macro_step());
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::PostStep(TS ts) {
  PetscFunctionBeginUser;
  WaveSolver* self;
  PetscCall(TSGetApplicationContext(ts, &self));
  PetscReal t;
  PetscCall(TSGetTime(ts, &t));
  const double h = t - self->time_;
  Vec u = nullptr, v = nullptr;
  PetscCall(self->GetFields(&u, &v));
  PetscScalar *U, *V;
  PetscCall(VecGetArray(u, &U));
  PetscCall(VecGetArray(v, &V));
  const SignalValues signal = SignalValues::At(self->excitation_.signal, t);
  for (const auto& term : self->terms_) term->Impose(signal, U, V);
  PetscCall(VecRestoreArray(v, &V));
  PetscCall(VecRestoreArray(u, &U));
  if (self->interface_ && !self->lts_active_) PetscCall(self->interface_->Commit(u, h));  // LTS: in its substeps
  PetscCall(self->RestoreFields(&u, &v));
  PetscCall(self->AccountStep(t, h));
  self->reaction_from_kick_ = false;
  self->time_ = t;
  ++self->steps_;
  PetscCall(self->CheckStableStep());
  if (self->steps_ % 50 == 0) PetscCall(self->CheckFinite(t, h));
  if (self->on_step) PetscCall(self->on_step(*self));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::CheckFinite(double t, double h) const {
  PetscFunctionBeginUser;
  // Local maximum and an explicit reduction: VecNorm may answer from a cached
  // norm of X_, which the TS updates through views without changing its state.
  const PetscScalar* x;
  PetscInt n;
  double local = 0.0, norm;
  PetscCall(VecGetLocalSize(X_, &n));
  PetscCall(VecGetArrayRead(X_, &x));
  for (PetscInt i = 0; i < n; ++i) {
    const double value = std::abs(PetscRealPart(x[i]));
    local = std::isfinite(value) ? std::max(local, value) : INFINITY;
  }
  PetscCall(VecRestoreArrayRead(X_, &x));
  MPI_Comm comm = PetscObjectComm((PetscObject)ts_);
  PetscCallMPI(MPI_Allreduce(&local, &norm, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCheck(std::isfinite(norm), comm, PETSC_ERR_NOT_CONVERGED,
             "wave solution blew up at step %" PetscInt_FMT " (t = %g s, dt = %g s, stability limit %g s): likely "
             "cause: a time step above the stability limit or a too stiff contact law",
             steps_, t, h, step_.stable_dt());
  PetscFunctionReturn(0);
}

PetscInt WaveSolver::StepsUntil(double t_end) const {
  return std::max<PetscInt>(0, static_cast<PetscInt>(std::floor((t_end - time_) / step_.dt() * (1.0 + 1e-12))));
}

PetscErrorCode WaveSolver::AdvanceSteps(PetscInt n) {
  PetscFunctionBeginUser;
  if (n <= 0) PetscFunctionReturn(0);
  PetscInt done;
  PetscCall(TSGetStepNumber(ts_, &done));
  PetscCall(TSSetTimeStep(ts_, step_.dt()));
  PetscCall(TSSetMaxSteps(ts_, done + n));
  PetscCall(TSSetMaxTime(ts_, 1e300));
  PetscCall(TSSolve(ts_, second_order_ ? u_view_ : X_));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::AdvanceTo(double t_end) {
  PetscFunctionBeginUser;
  // The TS's own MATCHSTEP goes through TSAdaptChoose, which basicsymplectic
  // never calls (it would step over t_end): land on t_end here.
  // dt may shrink while stepping (contact stiffening): count again until less than a step is left.
  for (PetscInt n = StepsUntil(t_end); n > 0; n = StepsUntil(t_end)) PetscCall(AdvanceSteps(n));
  const double remaining = t_end - time_;
  // Whole steps accumulate rounding in t (~1e-17 s after thousands of steps): a sliver step would divide a
  // step's energy by ~1e-17 s in the reported power. Below 1e-6 of a step, the clock is set onto t_end.
  if (remaining <= 1e-6 * step_.dt()) {
    if (remaining != 0.0) {
      PetscCall(TSSetTime(ts_, t_end));
      time_ = t_end;
    }
  } else {
    PetscInt done;
    PetscCall(TSGetStepNumber(ts_, &done));
    PetscCall(TSSetTimeStep(ts_, remaining));
    PetscCall(TSSetMaxSteps(ts_, done + 1));
    PetscCall(TSSolve(ts_, second_order_ ? u_view_ : X_));
    PetscCall(TSSetTimeStep(ts_, step_.dt()));
  }
  PetscFunctionReturn(0);
}

namespace {

/// Marks x changed (its cached norms are dropped): a write access does that,
/// without a collective.
PetscErrorCode TouchState(Vec x) {
  PetscScalar* a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(x, &a));
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode WaveSolver::KeepDampingEnergy(bool* kept) {
  PetscFunctionBeginUser;
  *kept = false;
  for (const auto& term : terms_) *kept = term->KeepDofEnergy() || *kept;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::TakeDampingEnergy(Vec e) {
  PetscFunctionBeginUser;
  PetscCall(VecSet(e, 0.0));
  PetscScalar* a;
  PetscCall(VecGetArray(e, &a));
  for (const auto& term : terms_) term->TakeDofEnergy(a);
  PetscCall(VecRestoreArray(e, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::GetFields(Vec* u, Vec* v) const {
  PetscFunctionBeginUser;
  // The TS changed X_ behind the views' backs: no cached norm of a view may survive.
  PetscCall(TouchState(u_));
  PetscCall(TouchState(v_));
  *u = u_;
  *v = v_;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::RestoreFields(Vec* u, Vec* v) const {
  PetscFunctionBeginUser;
  // The caller may have written through the views: X_ changed.
  PetscCall(TouchState(X_));
  *u = nullptr;
  *v = nullptr;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

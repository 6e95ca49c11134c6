#include "vibrotherm/wave/wave_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vibrotherm/wave/elastic_operator.hpp"
#include "vibrotherm/wave/stability.hpp"

namespace vibrotherm::wave {

PetscErrorCode ReadWaveOptions(MPI_Comm comm, WaveOptions* o) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Elastic waves", nullptr);
  PetscCall(PetscOptionsInt("-wave_degree", "Lagrange degree of the displacement (1 or 2)", nullptr, o->degree,
                            &o->degree, nullptr));
  PetscCall(PetscOptionsReal("-wave_cfl", "Time step as a fraction of the explicit stability limit", nullptr, o->cfl,
                             &o->cfl, nullptr));
  PetscCall(PetscOptionsReal("-wave_dt", "Time step [s] (default: cfl x stability limit)", nullptr, o->dt, &o->dt,
                             nullptr));
  PetscOptionsEnd();
  PetscCheck(o->degree == 1 || o->degree == 2, comm, PETSC_ERR_USER_INPUT, "-wave_degree must be 1 or 2, got %" PetscInt_FMT,
             o->degree);
  PetscCheck(o->cfl > 0.0 && o->cfl <= 1.0, comm, PETSC_ERR_USER_INPUT, "-wave_cfl must be in (0, 1], got %g", o->cfl);
  PetscCheck(o->dt >= 0.0, comm, PETSC_ERR_USER_INPUT, "-wave_dt must be > 0, got %g", o->dt);
  PetscFunctionReturn(0);
}

WaveSolver::~WaveSolver() {
  (void)TSDestroy(&ts_);
  if (u_view_) (void)VecRestoreSubVector(X_, is_u_, &u_view_);
  if (v_view_) (void)VecRestoreSubVector(X_, is_v_, &v_view_);
  (void)MatDestroy(&J_);
  for (Vec* v : {&X_, &force_, &M_, &Minv_, &traction_accel_}) (void)VecDestroy(v);
  (void)ISDestroy(&is_u_);
  (void)ISDestroy(&is_v_);
  (void)MatDestroy(&K_);
  (void)MatDestroy(&A_);
}

PetscErrorCode WaveSolver::Setup(DM dm, const ElasticMaterial& material, const Excitation& excitation,
                                 const WaveOptions& options) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  dm_ = dm;
  material_ = material;
  excitation_ = excitation;
  options_ = options;
  PetscCall(space_.Setup(dm, options.degree, 2));
  PetscCall(AssembleElasticOperators(space_, material, &K_, &M_));
  PetscCall(VecDuplicate(M_, &Minv_));
  PetscCall(VecCopy(M_, Minv_));
  PetscCall(VecReciprocal(Minv_));
  PetscCall(BuildWaveBoundary(space_, material, excitation, &boundary_));
  reaction_.assign(boundary_.constraints.size(), 0.0);

  PetscInt n, rstart;
  PetscCall(VecGetLocalSize(M_, &n));
  PetscCall(VecGetSize(M_, &global_dofs_));
  PetscCall(VecCreateMPI(comm, 2 * n, PETSC_DETERMINE, &X_));
  PetscCall(VecSet(X_, 0.0));
  PetscCall(VecGetOwnershipRange(X_, &rstart, nullptr));
  PetscCall(ISCreateStride(comm, n, rstart, 1, &is_u_));
  PetscCall(ISCreateStride(comm, n, rstart + n, 1, &is_v_));
  PetscCall(VecDuplicate(M_, &force_));
  dashpot_v_prev_.assign(2 * boundary_.dashpots.size(), 0.0);
  if (boundary_.traction_shape) {
    PetscCall(VecDuplicate(M_, &traction_accel_));
    PetscCall(VecPointwiseMult(traction_accel_, boundary_.traction_shape, Minv_));
    const PetscScalar* S;
    PetscCall(VecGetArrayRead(boundary_.traction_shape, &S));
    for (PetscInt i = 0; i < n; ++i)
      if (S[i] != 0.0) traction_dofs_.push_back(i);
    PetscCall(VecRestoreArrayRead(boundary_.traction_shape, &S));
    traction_u_prev_.assign(traction_dofs_.size(), 0.0);
  }

  PetscCall(TSCreate(comm, &ts_));
  PetscCall(TSSetOptionsPrefix(ts_, "wave_"));
  PetscCall(TSSetApplicationContext(ts_, this));
  PetscCall(TSSetProblemType(ts_, TS_NONLINEAR));
  PetscCall(TSSetType(ts_, TSBASICSYMPLECTIC));
  PetscCall(TSBasicSymplecticSetType(ts_, TSBASICSYMPLECTICVELVERLET));
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
  symplectic_ = std::string(type) == TSBASICSYMPLECTIC;
  second_order_ = std::string(type) == TSALPHA2;
  if (second_order_) {
    // The TS works on views of the state, so every other part sees its solution.
    PetscCall(VecGetSubVector(X_, is_u_, &u_view_));
    PetscCall(VecGetSubVector(X_, is_v_, &v_view_));
    PetscCall(TS2SetSolution(ts_, u_view_, v_view_));
    PetscCall(DMCreateMatrix(dm, &J_));
    PetscCall(TSSetI2Function(ts_, nullptr, I2Function, this));
    PetscCall(TSSetI2Jacobian(ts_, J_, J_, I2Jacobian, this));
    for (const Constraint& c : boundary_.constraints)
      PetscCheck(std::abs(c.d[0] * c.d[1]) < 1e-12, comm, PETSC_ERR_SUP,
                 "-wave_ts_type alpha2 supports prescribed components along x or y only (inclined source or roller "
                 "edge found)");
  } else {
    // An RHS function would be subtracted from an implicit residual: only for explicit types.
    PetscCall(TSSetRHSFunction(ts_, nullptr, RHSFull, this));
    PetscCall(TSRHSSplitSetRHSFunction(ts_, "position", nullptr, RHSPosition, this));
    PetscCall(TSRHSSplitSetRHSFunction(ts_, "momentum", nullptr, RHSMomentum, this));
  }
  // Types 1 and 2 kick once per step with coefficient 1: the trapezoidal dashpot is exact there.
  char scheme[16] = TSBASICSYMPLECTICVELVERLET;
  PetscCall(PetscOptionsGetString(nullptr, "wave_", "-ts_basicsymplectic_type", scheme, sizeof(scheme), nullptr));
  trapezoidal_kick_ = symplectic_ && (std::string(scheme) == "1" || std::string(scheme) == "2");
  velocity_verlet_ = symplectic_ && std::string(scheme) == "2";

  // Stable step: ω_max (SLEPc) and the measured (ω dt)_max of this TS type.
  double omega_dt_max;
  bool implicit;
  PetscCall(LargestAngularFrequency(K_, M_, &omega_max_));
  // A = −M⁻¹K scaled in place; alpha2 keeps K for its Jacobian.
  if (second_order_) {
    PetscCall(MatDuplicate(K_, MAT_COPY_VALUES, &A_));
  } else {
    A_ = K_;
    K_ = nullptr;
  }
  PetscCall(VecScale(Minv_, -1.0));
  PetscCall(MatDiagonalScale(A_, Minv_, nullptr));
  PetscCall(VecScale(Minv_, -1.0));
  PetscCall(OscillatorStabilityLimit("wave_", &omega_dt_max, &implicit));
  PetscCheck(implicit || omega_dt_max > 0.05, comm, PETSC_ERR_USER_INPUT,
             "-wave_ts_type %s is unstable for undamped waves (its stability region misses the imaginary axis); use "
             "basicsymplectic, rk with -wave_ts_rk_type 4, or ssp with -wave_ts_ssp_type rk104",
             type);
  omega_dt_max_ = implicit ? 0.0 : omega_dt_max;
  stable_dt_ = implicit ? INFINITY : omega_dt_max / omega_max_;
  const double reference_dt = implicit ? 2.0 / omega_max_ : stable_dt_;
  if (options.dt > 0.0) {
    PetscCheck(implicit || options.dt <= stable_dt_, comm, PETSC_ERR_USER_INPUT,
               "-wave_dt %g s exceeds the stability limit %g s of -wave_ts_type %s (omega_max %g rad/s); use "
               "-wave_dt <= %g or -wave_cfl",
               options.dt, stable_dt_, type, omega_max_, stable_dt_);
    dt_ = options.dt;
  } else {
    // Rounded down to 4 significant digits: the eigenvalue solve converges to
    // 1e-8, and its last digits differ with the number of ranks; a rounded step
    // keeps runs on different rank counts on the same time grid.
    const double raw = options.cfl * reference_dt, scale = std::pow(10.0, std::floor(std::log10(raw)) - 3);
    dt_ = std::floor(raw / scale) * scale;
  }
  PetscCall(TSSetTimeStep(ts_, dt_));
  PetscCall(TSSetTime(ts_, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Acceleration(double t, Vec u, Vec v, Vec a, double kick_dt) {
  PetscFunctionBeginUser;
  PetscCall(MatMult(A_, u, a));  // −M⁻¹K u
  if (interface_) PetscCall(interface_->AddAcceleration(u, a));
  double g, dg, ddg;
  excitation_.signal.evaluate(t, &g, &dg, &ddg);
  if (traction_accel_ && g != 0.0) PetscCall(VecAXPY(a, g, traction_accel_));
  PetscScalar* Acc;
  const PetscScalar *V, *Mass;
  PetscCall(VecGetArray(a, &Acc));
  PetscCall(VecGetArrayRead(v, &V));
  PetscCall(VecGetArrayRead(M_, &Mass));
  for (const Dashpot& d : boundary_.dashpots) {
    const PetscInt i = 2 * d.node;
    const double m = Mass[i], vx = V[i], vy = V[i + 1];
    const double fx = m * Acc[i] - (d.xx * vx + d.xy * vy), fy = m * Acc[i + 1] - (d.xy * vx + d.yy * vy);
    if (kick_dt > 0.0) {
      // (m I + h/2 C) acc = F − C v: the dashpot acts on the mean velocity of the kick.
      const double h = 0.5 * kick_dt;
      const double a11 = m + h * d.xx, a12 = h * d.xy, a22 = m + h * d.yy, det = a11 * a22 - a12 * a12;
      Acc[i] = (a22 * fx - a12 * fy) / det;
      Acc[i + 1] = (a11 * fy - a12 * fx) / det;
    } else {
      Acc[i] = fx / m;
      Acc[i + 1] = fy / m;
    }
  }
  PetscCall(VecRestoreArrayRead(v, &V));
  for (std::size_t k = 0; k < boundary_.constraints.size(); ++k) {
    const Constraint& c = boundary_.constraints[k];
    const PetscInt i = 2 * c.node;
    const double target = c.source ? ddg : 0.0, along = Acc[i] * c.d[0] + Acc[i + 1] * c.d[1];
    reaction_[k] = Mass[i] * (target - along);  // what the support adds along d
    Acc[i] += (target - along) * c.d[0];
    Acc[i + 1] += (target - along) * c.d[1];
  }
  PetscCall(VecRestoreArray(a, &Acc));
  PetscCall(VecRestoreArrayRead(M_, &Mass));
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
  Vec v;
  PetscReal h;
  PetscCall(TSGetTimeStep(self->ts_, &h));
  PetscCall(VecGetSubVector(self->X_, self->is_v_, &v));
  PetscCall(self->Acceleration(t, u, v, f, self->trapezoidal_kick_ ? h : 0.0));
  PetscCall(VecRestoreSubVector(self->X_, self->is_v_, &v));
  self->reaction_from_kick_ = self->trapezoidal_kick_;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::ImposeConstraints(double t, Vec u, Vec v) const {
  PetscFunctionBeginUser;
  if (boundary_.constraints.empty()) PetscFunctionReturn(0);
  double g, dg, ddg;
  excitation_.signal.evaluate(t, &g, &dg, &ddg);
  PetscScalar *U, *V;
  PetscCall(VecGetArray(u, &U));
  PetscCall(VecGetArray(v, &V));
  for (const Constraint& c : boundary_.constraints) {
    const PetscInt i = 2 * c.node;
    const double tu = c.source ? g : 0.0, tv = c.source ? dg : 0.0;
    const double au = U[i] * c.d[0] + U[i + 1] * c.d[1], av = V[i] * c.d[0] + V[i + 1] * c.d[1];
    U[i] += (tu - au) * c.d[0];
    U[i + 1] += (tu - au) * c.d[1];
    V[i] += (tv - av) * c.d[0];
    V[i + 1] += (tv - av) * c.d[1];
  }
  PetscCall(VecRestoreArray(u, &U));
  PetscCall(VecRestoreArray(v, &V));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::AccountStep(double t, double h) {
  PetscFunctionBeginUser;
  // Boundary quantities only: no full-vector copies, no reduction per step
  // (Energy() sums the ranks' accounts).
  Vec u, v;
  PetscCall(GetFields(&u, &v));
  const PetscScalar *U, *V;
  PetscCall(VecGetArrayRead(u, &U));
  PetscCall(VecGetArrayRead(v, &V));
  for (std::size_t k = 0; k < boundary_.dashpots.size(); ++k) {  // h v̄ᵀ C v̄ with the mean velocity of the step
    const Dashpot& d = boundary_.dashpots[k];
    const PetscInt i = 2 * d.node;
    const double vx = 0.5 * (V[i] + dashpot_v_prev_[2 * k]), vy = 0.5 * (V[i + 1] + dashpot_v_prev_[2 * k + 1]);
    accounted_.radiated += h * (d.xx * vx * vx + 2.0 * d.xy * vx * vy + d.yy * vy * vy);
    dashpot_v_prev_[2 * k] = V[i];
    dashpot_v_prev_[2 * k + 1] = V[i + 1];
  }
  double g, dg, ddg, g0, dg0, ddg0, gm, dgm, ddgm;
  excitation_.signal.evaluate(t, &g, &dg, &ddg);
  excitation_.signal.evaluate(t - h, &g0, &dg0, &ddg0);
  excitation_.signal.evaluate(t - 0.5 * h, &gm, &dgm, &ddgm);
  if (excitation_.type == SourceType::Displacement) {
    if (reaction_from_kick_) {  // the kick's support force times the prescribed displacement increment
      for (std::size_t k = 0; k < boundary_.constraints.size(); ++k)
        if (boundary_.constraints[k].source) accounted_.work_source += reaction_[k] * (g - g0);
    } else {  // trapezoid of the support power, the force evaluated at the end state
      PetscCall(Acceleration(t, u, v, force_, 0.0));
      double power = 0.0;
      for (std::size_t k = 0; k < boundary_.constraints.size(); ++k)
        if (boundary_.constraints[k].source) power += reaction_[k] * dg;
      accounted_.work_source += 0.5 * h * (source_power_prev_ + power);
      source_power_prev_ = power;
    }
  } else if (boundary_.traction_shape) {  // g(t_mid) f · Δu
    const PetscScalar* S;
    PetscCall(VecGetArrayRead(boundary_.traction_shape, &S));
    for (std::size_t k = 0; k < traction_dofs_.size(); ++k) {
      const PetscInt i = traction_dofs_[k];
      accounted_.work_source += gm * S[i] * (U[i] - traction_u_prev_[k]);
      traction_u_prev_[k] = U[i];
    }
    PetscCall(VecRestoreArrayRead(boundary_.traction_shape, &S));
  }
  PetscCall(VecRestoreArrayRead(u, &U));
  PetscCall(VecRestoreArrayRead(v, &V));
  PetscCall(RestoreFields(&u, &v));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::SetInterface(WaveInterface* interface, double expected_approach) {
  PetscFunctionBeginUser;
  PetscCheck(!second_order_, PetscObjectComm((PetscObject)dm_), PETSC_ERR_SUP,
             "-wave_ts_type alpha2 with a contact law is not supported yet: use an explicit type");
  interface_ = interface;
  if (omega_dt_max_ > 0.0 && options_.dt <= 0.0) {
    // A step that will rarely need to change: decided once, from the expected largest approach.
    double omega2;
    PetscCall(interface_->MaxFrequencySquared(&omega2, expected_approach));
    const double raw = options_.cfl * omega_dt_max_ / std::sqrt(omega_max_ * omega_max_ + omega2);
    const double scale = std::pow(10.0, std::floor(std::log10(raw)) - 3);
    dt_ = std::min(dt_, std::floor(raw / scale) * scale);
    PetscCall(TSSetTimeStep(ts_, dt_));
  }
  PetscCall(CheckStableStep());
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::CheckStableStep() {
  PetscFunctionBeginUser;
  if (!interface_ || omega_dt_max_ <= 0.0) PetscFunctionReturn(0);
  // The interface adds a positive semidefinite stiffness: ω² ≤ ω_bulk² + ω_interface² (Weyl).
  double omega2;
  PetscCall(interface_->MaxFrequencySquared(&omega2));
  const double limit = omega_dt_max_ / std::sqrt(omega_max_ * omega_max_ + omega2);
  if (dt_ > options_.cfl * limit * (1.0 + 1e-12)) {
    // Shrink with 50 % stiffness headroom: velocity Verlet wants a step that
    // changes rarely (a creeping step was measured to destabilise it).
    const double raw = options_.cfl * omega_dt_max_ / std::sqrt(omega_max_ * omega_max_ + 1.5 * omega2);
    const double scale = std::pow(10.0, std::floor(std::log10(raw)) - 3), reduced = std::floor(raw / scale) * scale;
    if (dt_reductions_ == 0 && steps_ > 0)
      PetscCall(PetscPrintf(PetscObjectComm((PetscObject)dm_),
                            "wave: the crack contact stiffened at t = %g s: time step reduced from %g to %g s "
                            "(further reductions are counted in summary.json)\n",
                            time_, dt_, reduced));
    if (steps_ > 0) ++dt_reductions_;
    dt_ = reduced;
    PetscCall(TSSetTimeStep(ts_, dt_));
  }
  stable_dt_ = limit;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::PostStep(TS ts) {
  PetscFunctionBeginUser;
  WaveSolver* self;
  PetscCall(TSGetApplicationContext(ts, &self));
  PetscReal t;
  PetscCall(TSGetTime(ts, &t));
  const double h = t - self->time_;
  Vec u, v;
  PetscCall(self->GetFields(&u, &v));
  PetscCall(self->ImposeConstraints(t, u, v));
  if (self->interface_) PetscCall(self->interface_->Commit(u, h));
  PetscCall(self->RestoreFields(&u, &v));
  PetscCall(self->AccountStep(t, h));
  self->reaction_from_kick_ = false;
  self->time_ = t;
  ++self->steps_;
  PetscCall(self->CheckStableStep());
  if (self->steps_ % 50 == 0) {
    // Local maximum and an explicit reduction: VecNorm may answer from a cached
    // norm of X_, which the TS updates through views without changing its state.
    const PetscScalar* x;
    PetscInt n;
    double local = 0.0, norm;
    PetscCall(VecGetLocalSize(self->X_, &n));
    PetscCall(VecGetArrayRead(self->X_, &x));
    for (PetscInt i = 0; i < n; ++i) {
      const double value = std::abs(PetscRealPart(x[i]));
      local = std::isfinite(value) ? std::max(local, value) : INFINITY;
    }
    PetscCall(VecRestoreArrayRead(self->X_, &x));
    PetscCallMPI(MPI_Allreduce(&local, &norm, 1, MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)ts)));
    PetscCheck(std::isfinite(norm), PetscObjectComm((PetscObject)ts), PETSC_ERR_NOT_CONVERGED,
               "wave solution blew up at step %" PetscInt_FMT " (t = %g s, dt = %g s, stability limit %g s): likely "
               "cause: a time step above the stability limit or a too stiff contact law",
               self->steps_, t, h, self->stable_dt_);
  }
  if (self->on_step) PetscCall(self->on_step(*self));
  PetscFunctionReturn(0);
}

PetscInt WaveSolver::StepsUntil(double t_end) const {
  return std::max<PetscInt>(0, static_cast<PetscInt>(std::floor((t_end - time_) / dt_ * (1.0 + 1e-12))));
}

PetscErrorCode WaveSolver::AdvanceSteps(PetscInt n) {
  PetscFunctionBeginUser;
  if (n <= 0) PetscFunctionReturn(0);
  PetscInt done;
  PetscCall(TSGetStepNumber(ts_, &done));
  PetscCall(TSSetTimeStep(ts_, dt_));
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
  if (remaining > 1e-9 * dt_) {
    PetscInt done;
    PetscCall(TSGetStepNumber(ts_, &done));
    PetscCall(TSSetTimeStep(ts_, remaining));
    PetscCall(TSSetMaxSteps(ts_, done + 1));
    PetscCall(TSSolve(ts_, second_order_ ? u_view_ : X_));
    PetscCall(TSSetTimeStep(ts_, dt_));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Forces(double t, Vec u, Vec v, Vec f) const {
  PetscFunctionBeginUser;
  PetscCall(MatMult(A_, u, f));
  PetscCall(VecPointwiseMult(f, f, M_));  // −K u
  double g, dg, ddg;
  excitation_.signal.evaluate(t, &g, &dg, &ddg);
  if (boundary_.traction_shape && g != 0.0) PetscCall(VecAXPY(f, g, boundary_.traction_shape));
  PetscScalar* F;
  const PetscScalar* V;
  PetscCall(VecGetArray(f, &F));
  PetscCall(VecGetArrayRead(v, &V));
  for (const Dashpot& d : boundary_.dashpots) {
    const PetscInt i = 2 * d.node;
    F[i] -= d.xx * V[i] + d.xy * V[i + 1];
    F[i + 1] -= d.xy * V[i] + d.yy * V[i + 1];
  }
  PetscCall(VecRestoreArrayRead(v, &V));
  PetscCall(VecRestoreArray(f, &F));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::I2Function(TS, PetscReal t, Vec U, Vec V, Vec A, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  PetscCall(self->Forces(t, U, V, F));  // F = f(U, V, t)
  PetscCall(VecScale(F, -1.0));
  PetscCall(VecPointwiseMult(self->force_, self->M_, A));
  PetscCall(VecAXPY(F, 1.0, self->force_));  // M A − f
  double g, dg, ddg;
  self->excitation_.signal.evaluate(t, &g, &dg, &ddg);
  PetscScalar* R;
  const PetscScalar *Acc, *Mass;
  PetscCall(VecGetArray(F, &R));
  PetscCall(VecGetArrayRead(A, &Acc));
  PetscCall(VecGetArrayRead(self->M_, &Mass));
  for (const Constraint& c : self->boundary_.constraints) {  // along d: m (A·d − ü_d)
    const PetscInt i = 2 * c.node;
    const double target = c.source ? ddg : 0.0, along = R[i] * c.d[0] + R[i + 1] * c.d[1];
    const double want = Mass[i] * ((Acc[i] * c.d[0] + Acc[i + 1] * c.d[1]) - target);
    R[i] += (want - along) * c.d[0];
    R[i + 1] += (want - along) * c.d[1];
  }
  PetscCall(VecRestoreArrayRead(self->M_, &Mass));
  PetscCall(VecRestoreArrayRead(A, &Acc));
  PetscCall(VecRestoreArray(F, &R));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::I2Jacobian(TS, PetscReal, Vec, Vec, Vec, PetscReal shiftV, PetscReal shiftA, Mat J, Mat,
                                      void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  PetscCall(MatCopy(self->K_, J, SAME_NONZERO_PATTERN));
  PetscCall(VecCopy(self->M_, self->force_));
  PetscCall(VecScale(self->force_, shiftA));
  PetscCall(MatDiagonalSet(J, self->force_, ADD_VALUES));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(self->M_, &rstart, nullptr));
  for (const Dashpot& d : self->boundary_.dashpots) {
    const PetscInt rows[2] = {rstart + 2 * d.node, rstart + 2 * d.node + 1};
    const PetscScalar block[4] = {shiftV * d.xx, shiftV * d.xy, shiftV * d.xy, shiftV * d.yy};
    PetscCall(MatSetValues(J, 2, rows, 2, rows, block, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  // Constrained rows (x or y): m shiftA on the diagonal, zero elsewhere.
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> diag;
  const PetscScalar* Mass;
  PetscCall(VecGetArrayRead(self->M_, &Mass));
  for (const Constraint& c : self->boundary_.constraints) {
    const PetscInt comp = std::abs(c.d[0]) > 0.5 ? 0 : 1;
    rows.push_back(rstart + 2 * c.node + comp);
    diag.push_back(Mass[2 * c.node] * shiftA);
  }
  PetscCall(VecRestoreArrayRead(self->M_, &Mass));
  PetscCall(MatZeroRows(J, static_cast<PetscInt>(rows.size()), rows.data(), 0.0, nullptr, nullptr));
  for (std::size_t k = 0; k < rows.size(); ++k) PetscCall(MatSetValue(J, rows[k], rows[k], diag[k], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::GetFields(Vec* u, Vec* v) const {
  PetscFunctionBeginUser;
  PetscCall(VecGetSubVector(X_, is_u_, u));
  PetscCall(VecGetSubVector(X_, is_v_, v));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::RestoreFields(Vec* u, Vec* v) const {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreSubVector(X_, is_v_, v));
  PetscCall(VecRestoreSubVector(X_, is_u_, u));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::Energy(WaveEnergy* e) const {
  PetscFunctionBeginUser;
  // With A = −M⁻¹K: uᵀKu = −(M∘u)·(A u).
  Vec u, v, Au, Mu;
  PetscCall(GetFields(&u, &v));
  PetscCall(VecDuplicate(u, &Au));
  PetscCall(VecDuplicate(u, &Mu));
  PetscCall(VecPointwiseMult(Mu, v, M_));
  PetscScalar kinetic, strain, vKv = 0.0;
  PetscCall(VecDot(Mu, v, &kinetic));
  if (velocity_verlet_) {
    PetscCall(MatMult(A_, v, Au));
    PetscCall(VecDot(Mu, Au, &vKv));
    vKv = -vKv;
  }
  PetscCall(VecPointwiseMult(Mu, u, M_));
  PetscCall(MatMult(A_, u, Au));
  PetscCall(VecDot(Mu, Au, &strain));
  PetscCall(VecDestroy(&Au));
  PetscCall(VecDestroy(&Mu));
  PetscCall(RestoreFields(&u, &v));
  double local[2] = {accounted_.radiated, accounted_.work_source}, global[2];
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  e->radiated = global[0];
  e->work_source = global[1];
  e->kinetic = 0.5 * PetscRealPart(kinetic);
  e->strain = -0.5 * PetscRealPart(strain);
  e->integrator = -dt_ * dt_ / 8.0 * PetscRealPart(vKv);
  if (interface_) PetscCall(interface_->Energies(&e->interface_stored, &e->dissipated));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

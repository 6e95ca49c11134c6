#include "vibrotherm/heat/heat_solver.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cmath>

#include "vibrotherm/fe/cell_matrix.hpp"
#include "vibrotherm/heat/heat_element.hpp"
#include "vibrotherm/heat/step_ladder.hpp"

namespace vibrotherm::heat {

const std::vector<OptionSpec<HeatMaterial>>& HeatMaterialOptionSpecs() {
  using M = HeatMaterial;
  using contact::Range;
  static const std::vector<OptionSpec<M>> specs = {
      RealOption("-heat_conductivity", &M::conductivity, Range::positive(), "W/(m K)", "Thermal conductivity k"),
      RealOption("-heat_capacity", &M::capacity, Range::positive(), "J/(kg K)", "Specific heat c_p"),
      RealOption("-heat_T0", &M::T0, Range::positive(), "K", "Initial and sink temperature"),
      RealOption("-material_expansion", &M::expansion, Range::at_least(0.0), "1/K",
                 "Linear thermal expansion coefficient (-thermoelastic)"),
  };
  return specs;
}

PetscErrorCode ReadHeatMaterial(MPI_Comm comm, double density, HeatMaterial* m, OptionValues* values) {
  PetscFunctionBeginUser;
  m->density = density;
  // Finite here too (CheckScene checks them later): -heat_T0 is the default of -heat_T_ext, checked first otherwise.
  PetscCall(ReadOptionSpecs(comm, "Heat conduction", HeatMaterialOptionSpecs(), m, values));
  PetscFunctionReturn(0);
}

const std::vector<OptionSpec<HeatOptions>>& HeatDiscretisationOptionSpecs() {
  using O = HeatOptions;
  static const std::vector<OptionSpec<O>> specs = {
      IntOption("-heat_degree", &O::degree, contact::Range::between(1, 2), "Lagrange degree of the temperature"),
      FlagOption("-heat_lumped_mass", &O::lumped, "Row-sum lumped heat capacity matrix (else consistent)"),
  };
  return specs;
}

PetscErrorCode ReadHeatOptions(MPI_Comm comm, double density, HeatOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadHeatMaterial(comm, density, &o->material, values));
  PetscCall(ReadOptionSpecs(comm, "Heat discretisation", HeatDiscretisationOptionSpecs(), o, values));
  PetscCall(ReadHeatBoundaryOptions(comm, o->material.T0, &o->boundary, values));
  PetscFunctionReturn(0);
}

HeatSolver::~HeatSolver() {
  (void)TSDestroy(&coupled_ts_);
  (void)TSDestroy(&free_ts_);
  for (Mat* m : {&M_, &K_}) (void)MatDestroy(m);
  for (Vec* v : {&theta_, &theta_prev_, &Q_, &G_, &H_, &work_, &residual_, &mix_}) (void)VecDestroy(v);
  for (Vec* v : {&partial_, &partial_load_, &partial_step_}) (void)VecDestroy(v);
}

PetscErrorCode HeatSolver::Setup(DM dm, const HeatOptions& options) {
  PetscFunctionBeginUser;
  dm_ = dm;
  material_ = options.material;
  PetscCall(space_.Setup(dm, options.degree, 1));
  PetscCall(AssembleMassAndConductivity(options.lumped));
  // Edges: the lumped film H on the diagonal of K, G = H (T_ext − T0).
  PetscCall(BuildHeatBoundary(space_, options.boundary, &boundary_));
  PetscCall(DMCreateGlobalVector(dm, &theta_));
  for (Vec* v : {&theta_prev_, &Q_, &G_, &H_, &work_, &residual_, &mix_}) PetscCall(VecDuplicate(theta_, v));
  for (Vec v : {theta_, theta_prev_, Q_, G_, H_}) PetscCall(VecSet(v, 0.0));
  PetscCall(AddConvectiveFilm());
  PetscCall(VecGetSize(theta_, &global_dofs_));
  // Backward Euler while coupled, -heat_substeps fixed steps per coupling interval,
  // each with its own friction energy. The source jumps at every step and the
  // layers at the crack are stiff (λΔt ≫ 1): Crank-Nicolson rings there (+27 %
  // at the crack centre at 0.1 ms with one step per interval, measured), backward
  // Euler is L-stable and its balance closes exactly (Account). The step is fixed:
  // the matrix is factored once.
  if (options.coupled_step > 0.0) PetscCall(StiffnessToMassRatio(1.0 / options.coupled_step, &coupled_stiffness_ratio_));
  PetscCall(CreateTS("heat_", TSBEULER, TSADAPTBASIC, &coupled_ts_));
  ts_ = coupled_ts_;
  // The free phase's TS now too, not when the waves stop: its options (-heat_free_*)
  // are read, and a bad one refused, before any step.
  PetscCall(RegisterStepLadder());  // geometric steps, one factorisation per rung (step_ladder.hpp)
  PetscCall(CreateTS("heat_free_", TSCN, kStepLadderAdapt, &free_ts_));
  PetscCall(responses_.Setup(
      K_, [this](double shift, Mat J) { return FillJacobian(shift, J); },
      [this](double shift, KSP ksp) {
        PetscFunctionBeginUser;
        PetscCall(KSPSetOptionsPrefix(ksp, "heat_response_"));
        PetscCall(ConfigureKsp(ksp));
        PetscCall(ConfigurePc(ksp, "heat_response_", shift));
        PetscCall(KSPSetFromOptions(ksp));
        PetscFunctionReturn(0);
      }));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AssembleMassAndConductivity(bool lumped) {
  PetscFunctionBeginUser;
  // M = ∫ρ c_p φ_a φ_b, K = ∫ k ∇φ_a·∇φ_b (assembled at the end of AddConvectiveFilm).
  PetscSection section;
  PetscCall(DMGetLocalSection(dm_, &section));
  // Row sums of P2 tetrahedra are negative at the vertices (−V/20): no lumped capacity there.
  PetscCheck(!(lumped && space_.simplex() && space_.degree() == 2 && space_.dim() == 3),
             PetscObjectComm((PetscObject)dm_), PETSC_ERR_SUP,
             "-heat_lumped_mass: row-sum lumping of P2 tetrahedra gives negative capacities; use the "
             "consistent mass or degree 1");
  PetscCall(fe::CreateCellMatrix(space_, {}, &M_));  // not DMPlexPreallocate: 1 ms a hexahedron (cell_matrix.hpp)
  PetscCall(MatDuplicate(M_, MAT_DO_NOT_COPY_VALUES, &K_));  // the same pattern: preallocated once
  const int Nb = space_.nodes_per_cell();
  std::vector<PetscScalar> Me(Nb * Nb), Ke(Nb * Nb);
  fe::CellQuadrature q;
  const double rc = material_.density * material_.capacity, k = material_.conductivity;
  for (PetscInt c : space_.cells()) {
    PetscCall(space_.Evaluate(c, &q));
    ElementHeatMatrices(q, rc, k, lumped, Me.data(), Ke.data());
    PetscCall(DMPlexMatSetClosure(dm_, section, nullptr, M_, c, Me.data(), ADD_VALUES));
    PetscCall(DMPlexMatSetClosure(dm_, section, nullptr, K_, c, Ke.data(), ADD_VALUES));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AddConvectiveFilm() {
  PetscFunctionBeginUser;
  for (std::size_t i = 0; i < boundary_.convective_rows.size(); ++i) {
    const PetscInt row = boundary_.convective_rows[i];
    const double hw = boundary_.convective_h[i];
    PetscCall(MatSetValue(K_, row, row, hw, ADD_VALUES));
    PetscCall(VecSetValue(H_, row, hw, INSERT_VALUES));
    PetscCall(VecSetValue(G_, row, hw * (boundary_.T_ext - material_.T0), INSERT_VALUES));
  }
  for (Mat m : {M_, K_}) {
    PetscCall(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY));
  }
  for (Vec v : {H_, G_}) {
    PetscCall(VecAssemblyBegin(v));
    PetscCall(VecAssemblyEnd(v));
  }
  PetscScalar film;
  PetscCall(VecSum(G_, &film));
  film_total_ = PetscRealPart(film);
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::CreateTS(const char* prefix, TSType type, TSAdaptType adapt_type, TS* ts) {
  PetscFunctionBeginUser;
  Mat J;  // the pattern of the assembled K (and M, assembled from the same closures)
  PetscCall(MatDuplicate(K_, MAT_DO_NOT_COPY_VALUES, &J));
  PetscCall(MatSetOption(J, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));  // zeroing rows must not shrink it
  PetscCall(TSCreate(PetscObjectComm((PetscObject)dm_), ts));
  PetscCall(TSSetOptionsPrefix(*ts, prefix));
  PetscCall(TSSetProblemType(*ts, TS_LINEAR));
  PetscCall(TSSetType(*ts, type));
  PetscCall(TSSetIFunction(*ts, nullptr, IFunction, this));
  PetscCall(TSSetIJacobian(*ts, J, J, IJacobian, this));
  PetscCall(MatDestroy(&J));
  PetscCall(TSSetApplicationContext(*ts, this));
  PetscCall(TSSetPostStep(*ts, PostStep));
  PetscCall(TSSetTime(*ts, time_));
  PetscCall(TSSetTimeStep(*ts, 1e-8));
  // Tolerances on the rise θ: relative 1e-4, absolute 1e-4 × the largest rise so
  // far (ScaleTolerance), 1e-12 K before anything has heated.
  PetscCall(TSSetTolerances(*ts, 1e-12, nullptr, 1e-4, nullptr));
  PetscCall(TSSetExactFinalTime(*ts, TS_EXACTFINALTIME_MATCHSTEP));
  TSAdapt adapt;
  PetscCall(TSGetAdapt(*ts, &adapt));
  PetscCall(TSAdaptSetType(adapt, adapt_type));
  SNES snes;
  KSP ksp;
  PetscCall(TSGetSNES(*ts, &snes));
  PetscCall(SNESSetType(snes, SNESKSPONLY));  // linear: one linear solve per stage
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(ConfigureStepSolver(*ts, ksp));
  PetscCall(TSSetFromOptions(*ts));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::SetSourceLoad(Vec load) {
  PetscFunctionBeginUser;
  if (load != Q_) PetscCall(VecCopy(load, Q_));
  PetscScalar total;
  PetscCall(VecSum(Q_, &total));
  load_total_ = PetscRealPart(total);
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::IFunction(TS, PetscReal, Vec theta, Vec theta_dot, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<HeatSolver*>(ctx);
  PetscCall(MatMult(self->M_, theta_dot, F));
  PetscCall(MatMultAdd(self->K_, theta, F, F));
  PetscCall(VecAXPY(F, -1.0, self->Q_));
  PetscCall(VecAXPY(F, -1.0, self->G_));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(F, &rstart, nullptr));
  PetscScalar* f;
  const PetscScalar* t;
  PetscCall(VecGetArray(F, &f));
  PetscCall(VecGetArrayRead(theta, &t));
  for (PetscInt row : self->boundary_.sink_rows) f[row - rstart] = t[row - rstart];
  PetscCall(VecRestoreArrayRead(theta, &t));
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::IJacobian(TS ts, PetscReal, Vec, Vec, PetscReal shift, Mat J, Mat, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<HeatSolver*>(ctx);
  // Linear problem: J depends on the shift alone. Leaving J untouched when the
  // shift repeats (equal coupling intervals) keeps the AMG setup of the last solve.
  // Equal steps differ in their last bits (t_next − t): a relative 1e-10 change
  // of the shift changes the one linear solve by as little, so J is kept.
  auto known = self->last_shift_.find(J);
  const bool kept = known != self->last_shift_.end() && std::abs(known->second - shift) <= 1e-10 * std::abs(shift);
  if (!kept) PetscCall(AssembleJacobian(self, shift, J));
  // The step's solver is that of the shift J holds (set up once per step length: rung_solvers.hpp).
  PetscCall(self->rungs_.at(ts)->Select(self->last_shift_.at(J)));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AssembleJacobian(HeatSolver* self, PetscReal shift, Mat J) {
  PetscFunctionBeginUser;
  self->last_shift_[J] = shift;
  PetscCall(self->FillJacobian(shift, J));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::FillJacobian(double shift, Mat J) const {
  PetscFunctionBeginUser;
  PetscCall(MatCopy(K_, J, SAME_NONZERO_PATTERN));
  PetscCall(MatAXPY(J, shift, M_, SAME_NONZERO_PATTERN));
  // Rows and columns: θ_sink is 0 in every iterate, so dropping its columns changes nothing but symmetry.
  const auto& rows = boundary_.sink_rows;
  PetscCall(MatZeroRowsColumns(J, static_cast<PetscInt>(rows.size()), rows.data(), 1.0, nullptr, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::PostStep(TS ts) {
  PetscFunctionBeginUser;
  HeatSolver* self;
  PetscReal t;
  PetscCall(TSGetApplicationContext(ts, &self));
  PetscCall(TSGetTime(ts, &t));
  self->last_step_ = t - self->time_;
  PetscCall(self->Account(self->last_step_));
  if (self->partial_) PetscCall(self->AdvancePartial());
  self->time_ = t;
  if (self->on_step) PetscCall(self->on_step(*self));
  if (self->stop_requested_) PetscCall(TSSetConvergedReason(ts, TS_CONVERGED_USER));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::Account(double h) {
  PetscFunctionBeginUser;
  deposited_ += h * load_total_;
  // The flux term is evaluated where the scheme evaluates it: θ_w = θ_{n−1} + w Δθ
  // with w = θ of the theta family (1: backward Euler, 1/2: Crank-Nicolson),
  // which makes content = deposited − loss exact for them. BDF has no such
  // weight (w = 1 here): its balance closes only to O(Δθ) per restart.
  double w;
  bool theta_family;
  PetscCall(ThetaWeight(ts_, &theta_family, &w));
  // r = M Δθ + h((K + H)θ_w − Q − G): the residual the sink rows would carry if free.
  Vec r = residual_, mix = mix_;
  PetscCall(VecWAXPY(work_, -1.0, theta_prev_, theta_));
  PetscCall(MatMult(M_, work_, r));
  PetscCall(VecWAXPY(mix, w, work_, theta_prev_));
  PetscCall(MatMult(K_, mix, work_));
  PetscCall(VecAXPY(work_, -1.0, Q_));
  PetscCall(VecAXPY(work_, -1.0, G_));
  PetscCall(VecAXPY(r, h, work_));
  double sink_local = 0.0, sink;
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(r, &rstart, nullptr));
  const PetscScalar* rr;
  PetscCall(VecGetArrayRead(r, &rr));
  for (PetscInt row : boundary_.sink_rows) sink_local += PetscRealPart(rr[row - rstart]);
  PetscCall(VecRestoreArrayRead(r, &rr));
  PetscCallMPI(MPI_Allreduce(&sink_local, &sink, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  PetscScalar film;
  PetscCall(VecDot(H_, mix, &film));
  boundary_loss_ += h * (PetscRealPart(film) - film_total_) - sink;
  PetscCall(VecCopy(theta_, theta_prev_));
  ++steps_;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ThetaWeight(TS ts, bool* family, double* w) {
  PetscFunctionBeginUser;
  PetscBool theta;
  PetscCall(PetscObjectTypeCompareAny((PetscObject)ts, &theta, TSTHETA, TSBEULER, TSCN, ""));
  *family = theta;
  PetscReal weight = 1.0;
  if (theta) PetscCall(TSThetaGetTheta(ts, &weight));
  *w = weight;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ScaleTolerance() {
  PetscFunctionBeginUser;
  // The rise can be anything from µK to K: the absolute tolerance follows the
  // largest rise so far, so -heat_ts_rtol means the same in every scene (read by
  // error-controlling adaptors only: -heat_free_ts_adapt_type basic, not the ladder).
  PetscReal peak;
  PetscCall(VecNorm(theta_, NORM_INFINITY, &peak));
  peak_rise_ = std::max(peak_rise_, static_cast<double>(peak));
  if (peak_rise_ > 0.0) {
    PetscReal rtol;
    PetscCall(TSGetTolerances(ts_, nullptr, nullptr, &rtol, nullptr));
    PetscCall(TSSetTolerances(ts_, rtol * peak_rise_, nullptr, rtol, nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::UseFreeIntegrator() {
  PetscFunctionBeginUser;
  if (ts_ == free_ts_) PetscFunctionReturn(0);
  // The ladder starts from the last coupled step (not the coupled TS's next-step
  // proposal, an error estimate's); nothing stepped yet: the TS's initial step.
  PetscReal dt = last_step_;
  if (dt <= 0.0) PetscCall(TSGetTimeStep(ts_, &dt));
  PetscCall(TSSetTime(free_ts_, time_));
  PetscCall(TSSetTimeStep(free_ts_, dt));
  TSAdapt adapt;
  PetscCall(TSGetAdapt(free_ts_, &adapt));
  PetscCall(StepLadderStart(adapt, dt));  // a first segment shorter than dt must not set the rung
  ts_ = free_ts_;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::UseCoupledIntegrator() {
  PetscFunctionBeginUser;
  if (ts_ == coupled_ts_) PetscFunctionReturn(0);
  PetscCall(TSSetTime(coupled_ts_, time_));
  ts_ = coupled_ts_;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AdvanceInSteps(double t_end, PetscInt steps) {
  PetscFunctionBeginUser;
  if (t_end <= time_) PetscFunctionReturn(0);
  // One TSSolve per step: the adaptor stays on (theta methods allocate its
  // history only when it is on at setup) but accepts each step as given.
  TSAdapt adapt;
  PetscCall(TSGetAdapt(ts_, &adapt));
  PetscCall(TSAdaptSetAlwaysAccept(adapt, PETSC_TRUE));
  const double t_start = time_;
  for (PetscInt k = 1; k <= steps; ++k) {
    const double t_next = k == steps ? t_end : t_start + (t_end - t_start) * k / steps;
    PetscInt done;
    PetscCall(TSGetStepNumber(ts_, &done));
    PetscCall(TSSetTimeStep(ts_, t_next - time_));
    PetscCall(TSSetMaxTime(ts_, t_next));
    PetscCall(TSSetMaxSteps(ts_, done + 1));
    PetscCall(TSSolve(ts_, theta_));
  }
  PetscCall(TSAdaptSetAlwaysAccept(adapt, PETSC_FALSE));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AdvanceTo(double t_end) {
  PetscFunctionBeginUser;
  if (t_end <= time_) PetscFunctionReturn(0);
  PetscCall(UseFreeIntegrator());
  PetscCall(ScaleTolerance());
  PetscCall(TSSetMaxTime(ts_, t_end));
  PetscCall(TSSetMaxSteps(ts_, PETSC_MAX_INT));
  PetscCall(TSSolve(ts_, theta_));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::Accounts(HeatAccounts* accounts) const {
  PetscFunctionBeginUser;
  accounts->deposited = deposited_;
  accounts->boundary_loss = boundary_loss_;
  PetscCall(MatMult(M_, theta_, work_));  // ∫ρ c_p θ = 1ᵀ M θ
  PetscScalar sum;
  PetscCall(VecSum(work_, &sum));
  accounts->content = PetscRealPart(sum);
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::LumpedCapacityInverse(Vec* inverse) const {
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(theta_, inverse));
  PetscCall(MatGetRowSum(M_, *inverse));
  PetscCall(VecReciprocal(*inverse));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(*inverse, &rstart, nullptr));
  PetscScalar* c;
  PetscCall(VecGetArray(*inverse, &c));
  for (PetscInt row : boundary_.sink_rows) c[row - rstart] = 0.0;
  PetscCall(VecRestoreArray(*inverse, &c));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat

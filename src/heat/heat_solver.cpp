#include "vibrotherm/heat/heat_solver.hpp"

#include <petscdmplex.h>

#include <cmath>
#include <set>

#include "vibrotherm/mesh/labels.hpp"
#include "vibrotherm/mesh/plex_access.hpp"

namespace vibrotherm::heat {

PetscErrorCode ReadHeatMaterial(MPI_Comm comm, double density, HeatMaterial* m) {
  PetscFunctionBeginUser;
  m->density = density;
  PetscOptionsBegin(comm, nullptr, "Heat conduction", nullptr);
  PetscCall(PetscOptionsReal("-heat_conductivity", "Thermal conductivity k [W/(m K)]", nullptr, m->conductivity,
                             &m->conductivity, nullptr));
  PetscCall(PetscOptionsReal("-heat_capacity", "Specific heat c_p [J/(kg K)]", nullptr, m->capacity, &m->capacity, nullptr));
  PetscCall(PetscOptionsReal("-heat_T0", "Initial and sink temperature [K]", nullptr, m->T0, &m->T0, nullptr));
  PetscOptionsEnd();
  PetscCheck(m->conductivity > 0, comm, PETSC_ERR_USER_INPUT, "-heat_conductivity must be > 0, got %g", m->conductivity);
  PetscCheck(m->capacity > 0, comm, PETSC_ERR_USER_INPUT, "-heat_capacity must be > 0, got %g", m->capacity);
  PetscFunctionReturn(0);
}

HeatSolver::~HeatSolver() {
  (void)TSDestroy(&ts_);
  for (Mat* m : {&M_, &K_}) (void)MatDestroy(m);
  for (Vec* v : {&T_, &Q_, &work_}) (void)VecDestroy(v);
}

PetscErrorCode HeatSolver::Setup(DM dm, const HeatMaterial& material) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  dm_ = dm;
  material_ = material;
  PetscInt degree = 1;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-heat_degree", &degree, nullptr));
  PetscCheck(degree == 1 || degree == 2, comm, PETSC_ERR_USER_INPUT, "-heat_degree must be 1 or 2, got %" PetscInt_FMT, degree);
  PetscCall(space_.Setup(dm, degree, 1));

  // M = ∫ρ c_p φ_a φ_b, K = ∫ k ∇φ_a·∇φ_b.
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMCreateMatrix(dm, &M_));
  PetscCall(DMCreateMatrix(dm, &K_));
  const int Nb = space_.nodes_per_cell();
  std::vector<PetscScalar> Me(Nb * Nb), Ke(Nb * Nb);
  fe::CellQuadrature q;
  const double rc = material.density * material.capacity, k = material.conductivity;
  for (PetscInt c : space_.cells()) {
    PetscCall(space_.Evaluate(c, &q));
    std::fill(Me.begin(), Me.end(), 0.0);
    std::fill(Ke.begin(), Ke.end(), 0.0);
    for (int p = 0; p < q.points; ++p) {
      const double* phi = q.value + p * Nb;
      const double* g = &q.grad[p * Nb * 2];
      for (int a = 0; a < Nb; ++a)
        for (int b = 0; b < Nb; ++b) {
          Me[a * Nb + b] += q.weight[p] * rc * phi[a] * phi[b];
          Ke[a * Nb + b] += q.weight[p] * k * (g[2 * a] * g[2 * b] + g[2 * a + 1] * g[2 * b + 1]);
        }
    }
    PetscCall(DMPlexMatSetClosure(dm, section, nullptr, M_, c, Me.data(), ADD_VALUES));
    PetscCall(DMPlexMatSetClosure(dm, section, nullptr, K_, c, Ke.data(), ADD_VALUES));
  }
  for (Mat m : {M_, K_}) {
    PetscCall(MatAssemblyBegin(m, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(m, MAT_FINAL_ASSEMBLY));
  }

  // Sink rows: owned dofs on faces labelled sink (their vertices and, for degree 2, the edge).
  PetscSection global;
  PetscCall(DMGetGlobalSection(dm, &global));
  std::set<PetscInt> rows;
  DMLabel sink;
  PetscCall(DMGetLabel(dm, mesh::labels::sink, &sink));
  IS faces = nullptr;
  if (sink) PetscCall(DMLabelGetStratumIS(sink, 1, &faces));
  if (faces) {
    PetscInt nf;
    const PetscInt* f;
    PetscCall(ISGetLocalSize(faces, &nf));
    PetscCall(ISGetIndices(faces, &f));
    for (PetscInt i = 0; i < nf; ++i) {
      PetscInt depth;
      PetscCall(DMPlexGetPointDepth(dm, f[i], &depth));
      if (depth != 1) continue;
      const PetscInt* cone;
      PetscCall(DMPlexGetCone(dm, f[i], &cone));
      for (PetscInt point : {cone[0], cone[1], f[i]}) {
        PetscInt dof, off;
        PetscCall(PetscSectionGetDof(global, point, &dof));
        PetscCall(PetscSectionGetOffset(global, point, &off));
        if (dof > 0 && off >= 0) rows.insert(off);  // negative offset: owned by another rank
      }
    }
    PetscCall(ISRestoreIndices(faces, &f));
    PetscCall(ISDestroy(&faces));
  }
  sink_rows_.assign(rows.begin(), rows.end());

  // Crack facets this rank owns (each facet counted once), with their face weights.
  DMLabel ids;
  PetscCall(DMGetLabel(dm, mesh::labels::crack_face, &ids));
  std::vector<bool> ghost;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &fStart, &fEnd));
  facets_.clear();
  for (PetscInt f = fStart; f < fEnd && ids; ++f) {
    PetscInt id;
    PetscCall(DMLabelGetValue(ids, f, &id));
    if (id < 0 || ghost[f - chart0]) continue;
    FacetLoad load{id, {}, {}};
    double length;
    PetscCall(space_.FaceNodes(f, &load.local_offsets, &load.weights, &length));
    facets_.push_back(std::move(load));
  }

  PetscCall(DMCreateGlobalVector(dm, &T_));
  PetscCall(VecSet(T_, material.T0));
  PetscCall(VecDuplicate(T_, &Q_));
  PetscCall(VecSet(Q_, 0.0));
  PetscCall(VecDuplicate(T_, &work_));

  Mat J;  // the pattern of the assembled K (and M, assembled from the same closures)
  PetscCall(MatDuplicate(K_, MAT_DO_NOT_COPY_VALUES, &J));
  PetscCall(MatSetOption(J, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));  // MatZeroRows must not shrink it
  PetscCall(TSCreate(comm, &ts_));
  PetscCall(TSSetOptionsPrefix(ts_, "heat_"));
  PetscCall(TSSetProblemType(ts_, TS_LINEAR));
  PetscCall(TSSetType(ts_, TSBDF));
  PetscCall(TSSetIFunction(ts_, nullptr, IFunction, this));
  PetscCall(TSSetIJacobian(ts_, J, J, IJacobian, this));
  PetscCall(MatDestroy(&J));
  PetscCall(TSSetTimeStep(ts_, 1e-8));
  PetscCall(TSSetExactFinalTime(ts_, TS_EXACTFINALTIME_MATCHSTEP));
  // Linear problem: one linear solve per stage; CG does not apply (the sink rows
  // break symmetry), GMRES with hypre BoomerAMG (GAMG diverged once BDF grew the step).
  SNES snes;
  KSP ksp;
  PC pc;
  PetscCall(TSGetSNES(ts_, &snes));
  PetscCall(SNESSetType(snes, SNESKSPONLY));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPSetTolerances(ksp, 1e-12, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCHYPRE));
  PetscCall(TSSetFromOptions(ts_));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::SetCrackPower(const std::vector<double>& power) {
  PetscFunctionBeginUser;
  Vec local;
  PetscCall(DMGetLocalVector(dm_, &local));
  PetscCall(VecSet(local, 0.0));
  PetscScalar* q;
  PetscCall(VecGetArray(local, &q));
  for (const FacetLoad& f : facets_) {
    PetscCheck(f.id < static_cast<PetscInt>(power.size()), PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
               "crack power given for %zu facets, facet id %" PetscInt_FMT " exists", power.size(), f.id);
    for (std::size_t j = 0; j < f.local_offsets.size(); ++j) q[f.local_offsets[j]] += power[f.id] * f.weights[j];
  }
  PetscCall(VecRestoreArray(local, &q));
  PetscCall(VecSet(Q_, 0.0));
  PetscCall(DMLocalToGlobal(dm_, local, ADD_VALUES, Q_));
  PetscCall(DMRestoreLocalVector(dm_, &local));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::IFunction(TS, PetscReal, Vec T, Vec Tdot, Vec F, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<HeatSolver*>(ctx);
  PetscCall(MatMult(self->M_, Tdot, F));
  PetscCall(MatMultAdd(self->K_, T, F, F));
  PetscCall(VecAXPY(F, -1.0, self->Q_));
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(F, &rstart, nullptr));
  PetscScalar* f;
  const PetscScalar* t;
  PetscCall(VecGetArray(F, &f));
  PetscCall(VecGetArrayRead(T, &t));
  for (PetscInt row : self->sink_rows_) f[row - rstart] = t[row - rstart] - self->material_.T0;
  PetscCall(VecRestoreArrayRead(T, &t));
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::IJacobian(TS, PetscReal, Vec, Vec, PetscReal shift, Mat J, Mat, void* ctx) {
  PetscFunctionBeginUser;
  auto* self = static_cast<HeatSolver*>(ctx);
  PetscCall(MatCopy(self->K_, J, SAME_NONZERO_PATTERN));
  PetscCall(MatAXPY(J, shift, self->M_, SAME_NONZERO_PATTERN));
  PetscCall(MatZeroRows(J, static_cast<PetscInt>(self->sink_rows_.size()), self->sink_rows_.data(), 1.0, nullptr, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::AdvanceTo(double t_end) {
  PetscFunctionBeginUser;
  if (t_end <= time_) PetscFunctionReturn(0);
  PetscCall(TSSetMaxTime(ts_, t_end));
  PetscCall(TSSetMaxSteps(ts_, PETSC_MAX_INT));
  PetscCall(TSSolve(ts_, T_));
  PetscReal t;
  PetscCall(TSGetTime(ts_, &t));
  time_ = t;
  PetscCall(TSGetStepNumber(ts_, &steps_));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::TemperatureAt(double x, double y, double* T) const {
  PetscFunctionBeginUser;
  PetscInt cell;
  std::array<double, 2> ref;
  PetscCall(space_.Locate(x, y, &cell, &ref));
  double local[2] = {0.0, 0.0};
  Vec l;  // collective: every rank fills its local vector
  PetscCall(DMGetLocalVector(dm_, &l));
  PetscCall(DMGlobalToLocal(dm_, T_, INSERT_VALUES, l));
  if (cell >= 0) {
    std::vector<double> phi;
    PetscCall(space_.BasisAt(ref, &phi));
    PetscSection section;
    PetscScalar* c = nullptr;
    PetscInt n;
    PetscCall(DMGetLocalSection(dm_, &section));
    PetscCall(DMPlexVecGetClosure(dm_, section, l, cell, &n, &c));
    for (std::size_t b = 0; b < phi.size(); ++b) local[0] += phi[b] * PetscRealPart(c[b]);
    PetscCall(DMPlexVecRestoreClosure(dm_, section, l, cell, &n, &c));
    local[1] = 1.0;
  }
  PetscCall(DMRestoreLocalVector(dm_, &l));
  double global[2];
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm_)));
  *T = global[1] > 0 ? global[0] / global[1] : NAN;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::HeatContent(double* content) const {
  PetscFunctionBeginUser;
  Vec d;
  PetscCall(VecDuplicate(T_, &d));
  PetscCall(VecCopy(T_, d));
  PetscCall(VecShift(d, -material_.T0));
  PetscCall(MatMult(M_, d, work_));
  PetscScalar sum;
  PetscCall(VecSum(work_, &sum));
  *content = PetscRealPart(sum);
  PetscCall(VecDestroy(&d));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat

// The harmonic start (-wave_start harmonic): the waves begin in the steady
// response of the linearized problem to the source at its frequency, as if it
// had always run. A lightly damped specimen (-material_loss_factor 1e-3) driven
// at a mode builds up over ~2/(η ω) ≈ 5–15 ms, hundreds of periods that a real
// test spends once but a simulation would pay for before any periodic
// continuation; from the steady linear state only the contact's own nonlinearity
// is left to settle. With u(t) = Im(U e^{iωt}) and the source g = A sin ωt:
//   (K + K_c − ω² M + iω (α M + C_dashpots)) U = F,
// K_c the interface's tangent stiffness at its initial state (all springs stuck),
// F the traction source's load (or the prescribed component U = A on the source
// nodes, 0 on the other constrained ones). Solved as the real system of twice the
// size, real and imaginary parts interleaved per dof, by MUMPS (-wave_harmonic_
// prefix). Then u(0) = Im U, v(0) = ω Re U; the interface keeps its virgin history
// at rest, so its first trial at u(0) is the stuck springs the solve assumed; the
// initial energy (kinetic, strain, the stuck springs') is booked as the source's
// work at t = 0, which keeps the energy budget closed.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vibrotherm/util/heartbeat.hpp"
#include "vibrotherm/wave/factor_memory.hpp"
#include "vibrotherm/wave/harmonic_start.hpp"
#include "vibrotherm/wave/harmonic_krylov.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {
namespace {

/// Z(2r + part, 2c + part) += v for part in {0, 1} (the same real block on both parts).
PetscErrorCode AddBoth(Mat Z, PetscInt r, PetscInt c, double v) {
  PetscFunctionBeginUser;
  PetscCall(MatSetValue(Z, 2 * r, 2 * c, v, ADD_VALUES));
  PetscCall(MatSetValue(Z, 2 * r + 1, 2 * c + 1, v, ADD_VALUES));
  PetscFunctionReturn(0);
}

/// The damping block b = ω C_rc: −b on (real row, imaginary column), +b on (imaginary row, real column).
PetscErrorCode AddDamping(Mat Z, PetscInt r, PetscInt c, double b) {
  PetscFunctionBeginUser;
  PetscCall(MatSetValue(Z, 2 * r, 2 * c + 1, -b, ADD_VALUES));
  PetscCall(MatSetValue(Z, 2 * r + 1, 2 * c, b, ADD_VALUES));
  PetscFunctionReturn(0);
}

/// Per owned row of A: copies × its entries + extra (the preallocation of a matrix built from A's rows).
PetscErrorCode StiffnessRowLengths(Mat A, PetscInt copies, PetscInt extra, std::vector<PetscInt>* lengths) {
  PetscFunctionBeginUser;
  PetscInt rstart, rend;
  PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
  lengths->assign(static_cast<std::size_t>(copies * (rend - rstart)), 0);
  for (PetscInt g = rstart; g < rend; ++g) {
    PetscInt ncols;
    PetscCall(MatGetRow(A, g, &ncols, nullptr, nullptr));
    for (PetscInt part = 0; part < copies; ++part) (*lengths)[copies * (g - rstart) + part] = copies * ncols + extra;
    PetscCall(MatRestoreRow(A, g, &ncols, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

/// The iterative solve's outcome on the console. One that did not converge, or whose true residual
/// ‖Z U − rhs‖ is above 10 × its tolerance (some Krylov types stop on an estimate), is an error naming
/// the options that help.
PetscErrorCode ReportHarmonicSolve(KSP ksp, Mat Z, Vec rhs, Vec U) {
  PetscFunctionBeginUser;
  KSPType type;
  PetscCall(KSPGetType(ksp, &type));
  if (std::string(type) == KSPPREONLY) PetscFunctionReturn(0);
  PetscInt iterations;
  KSPConvergedReason reason;
  PetscReal rtol, rhs_norm, residual;
  PetscCall(KSPGetIterationNumber(ksp, &iterations));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(KSPGetTolerances(ksp, &rtol, nullptr, nullptr, nullptr));
  Vec r;
  PetscCall(VecDuplicate(rhs, &r));
  PetscCall(MatMult(Z, U, r));
  PetscCall(VecAXPY(r, -1.0, rhs));
  PetscCall(VecNorm(r, NORM_2, &residual));
  PetscCall(VecNorm(rhs, NORM_2, &rhs_norm));
  PetscCall(VecDestroy(&r));
  const double relative = rhs_norm > 0.0 ? residual / rhs_norm : residual;
  MPI_Comm comm = PetscObjectComm((PetscObject)ksp);
  PetscCheck(reason > 0 && relative <= 10.0 * rtol, comm, PETSC_ERR_NOT_CONVERGED,
             "Harmonic start: the Krylov solve (%s) did not converge (%s after %" PetscInt_FMT " iterations, true "
             "residual %.3g of the load): raise -wave_harmonic_ksp_max_it or -wave_harmonic_ksp_gmres_restart, or use "
             "-wave_harmonic_solver direct",
             type, KSPConvergedReasons[reason], iterations, relative);
  PetscCall(PetscPrintf(comm, "Harmonic start: %s converged in %" PetscInt_FMT " iterations (true residual %.2g of the "
                        "load)\n", type, iterations, relative));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode HarmonicStart::AddLinearizedStiffness(double mass_coefficient, const EntryAdder& add) const {
  PetscFunctionBeginUser;
  PetscInt rstart, rend;
  PetscCall(VecGetOwnershipRange(op_.M, &rstart, &rend));
  const PetscScalar* m;
  PetscCall(VecGetArrayRead(op_.M, &m));
  for (PetscInt g = rstart; g < rend; ++g) {  // K = −M A (A = −M⁻¹K), then the mass term
    const PetscInt i = g - rstart, *cols;
    const PetscScalar* values;
    PetscInt ncols;
    PetscCall(MatGetRow(op_.A, g, &ncols, &cols, &values));
    for (PetscInt k = 0; k < ncols; ++k) PetscCall(add(g, cols[k], -m[i] * PetscRealPart(values[k])));
    PetscCall(MatRestoreRow(op_.A, g, &ncols, &cols, &values));
    PetscCall(add(g, g, mass_coefficient * m[i]));
  }
  PetscCall(VecRestoreArrayRead(op_.M, &m));
  if (op_.interface) {
    std::vector<PetscInt> rows, cols;
    std::vector<double> values;
    PetscCall(op_.interface->TangentStiffness(&rows, &cols, &values));
    for (std::size_t k = 0; k < rows.size(); ++k) PetscCall(add(rows[k], cols[k], values[k]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HarmonicStart::Constraints(std::vector<PetscInt>* dofs, std::vector<double>* values) const {
  PetscFunctionBeginUser;
  PetscInt rstart;
  PetscCall(VecGetOwnershipRange(op_.M, &rstart, nullptr));
  const int D = op_.boundary->dim;
  for (const Constraint& c : op_.boundary->constraints) {
    int axis = 0;
    while (axis + 1 < D && !(std::abs(c.d[axis]) > 1.0 - 1e-12)) ++axis;
    PetscCheck(std::abs(c.d[axis]) > 1.0 - 1e-12, PetscObjectComm((PetscObject)op_.dm), PETSC_ERR_SUP,
               "-wave_start harmonic: a constrained direction (%g, %g, %g) is not along a coordinate axis", c.d[0],
               c.d[1], c.d[2]);
    dofs->push_back(rstart + D * c.node + axis);
    values->push_back(c.source ? op_.excitation->signal.amplitude * c.d[axis] : 0.0);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HarmonicStart::Assemble(double omega, Mat* Z, Vec* rhs) const {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)op_.dm);
  PetscInt n, rstart;
  PetscCall(VecGetLocalSize(op_.M, &n));
  PetscCall(VecGetOwnershipRange(op_.M, &rstart, nullptr));
  std::vector<PetscInt> nnz;
  PetscCall(StiffnessRowLengths(op_.A, 2, 16, &nnz));  // K on both parts, the damping blocks, a contact cell
  PetscCall(MatCreateAIJ(comm, 2 * n, 2 * n, PETSC_DETERMINE, PETSC_DETERMINE, 0, nnz.data(), 0, nnz.data(), Z));
  PetscCall(MatSetOption(*Z, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatCreateVecs(*Z, nullptr, rhs));
  PetscCall(AddLinearizedStiffness(-omega * omega, [Z](PetscInt r, PetscInt c, double v) { return AddBoth(*Z, r, c, v); }));
  if (op_.material->damping_rate > 0.0) {  // ω α M
    const PetscScalar* m;
    PetscCall(VecGetArrayRead(op_.M, &m));
    for (PetscInt i = 0; i < n; ++i) PetscCall(AddDamping(*Z, rstart + i, rstart + i, omega * op_.material->damping_rate * m[i]));
    PetscCall(VecRestoreArrayRead(op_.M, &m));
  }
  const int D = op_.boundary->dim;
  for (std::size_t k = 0; k < op_.boundary->dashpots.size(); ++k) {
    const PetscInt first = rstart + D * op_.boundary->dashpots.nodes[k];
    for (int p = 0; p < D; ++p)
      for (int q = 0; q < D; ++q)
        PetscCall(AddDamping(*Z, first + p, first + q, omega * op_.boundary->dashpots.at(k, p, q)));
  }
  PetscCall(MatAssemblyBegin(*Z, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*Z, MAT_FINAL_ASSEMBLY));
  if (op_.excitation->type == SourceType::Traction) {  // F = A · shape, a real phasor
    const PetscScalar* shape;
    PetscScalar* f;
    PetscCall(VecGetArrayRead(op_.boundary->traction_shape, &shape));
    PetscCall(VecGetArray(*rhs, &f));
    for (PetscInt i = 0; i < n; ++i) f[2 * i] = op_.excitation->signal.amplitude * shape[i];
    PetscCall(VecRestoreArray(*rhs, &f));
    PetscCall(VecRestoreArrayRead(op_.boundary->traction_shape, &shape));
  }
  // Constrained components: their rows and columns by the prescribed values (real A on the source's).
  std::vector<PetscInt> dofs, fixed;
  std::vector<double> values;
  PetscCall(Constraints(&dofs, &values));
  Vec known;
  PetscCall(VecDuplicate(*rhs, &known));
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    fixed.insert(fixed.end(), {2 * dofs[k], 2 * dofs[k] + 1});
    PetscCall(VecSetValue(known, 2 * dofs[k], values[k], INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(known));
  PetscCall(VecAssemblyEnd(known));
  PetscCall(MatZeroRowsColumns(*Z, static_cast<PetscInt>(fixed.size()), fixed.data(), 1.0, known, *rhs));
  PetscCall(VecDestroy(&known));
  PetscFunctionReturn(0);
}

PetscErrorCode HarmonicStart::AssemblePreconditioner(double omega, Mat* P) const {
  PetscFunctionBeginUser;
  PetscInt n;
  PetscCall(VecGetLocalSize(op_.M, &n));
  std::vector<PetscInt> nnz;
  PetscCall(StiffnessRowLengths(op_.A, 1, 8, &nnz));
  PetscCall(MatCreateAIJ(PetscObjectComm((PetscObject)op_.dm), n, n, PETSC_DETERMINE, PETSC_DETERMINE, 0, nnz.data(), 0,
                         nnz.data(), P));
  PetscCall(MatSetBlockSize(*P, op_.boundary->dim));
  PetscCall(MatSetOption(*P, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(AddLinearizedStiffness(omega * omega, [P](PetscInt r, PetscInt c, double v) {
    return MatSetValue(*P, r, c, v, ADD_VALUES);
  }));
  PetscCall(MatAssemblyBegin(*P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*P, MAT_FINAL_ASSEMBLY));
  std::vector<PetscInt> dofs;
  std::vector<double> values;
  PetscCall(Constraints(&dofs, &values));
  PetscCall(MatZeroRowsColumns(*P, static_cast<PetscInt>(dofs.size()), dofs.data(), 1.0, nullptr, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode HarmonicStart::NodePositionVector(Vec* coordinates) const {
  PetscFunctionBeginUser;
  std::vector<double> positions;  // in the local section's layout: dof (node, axis) holds x_axis
  PetscCall(op_.space->NodePositions(&positions));
  Vec local;
  PetscCall(DMGetLocalVector(op_.dm, &local));
  PetscInt size;
  PetscCall(VecGetLocalSize(local, &size));
  PetscCheck(static_cast<std::size_t>(size) == positions.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "harmonic start: %zu node positions for a local vector of %" PetscInt_FMT, positions.size(), size);
  PetscScalar* x;
  PetscCall(VecGetArray(local, &x));
  std::copy(positions.begin(), positions.end(), x);
  PetscCall(VecRestoreArray(local, &x));
  PetscCall(DMCreateGlobalVector(op_.dm, coordinates));
  PetscCall(DMLocalToGlobal(op_.dm, local, INSERT_VALUES, *coordinates));
  PetscCall(DMRestoreLocalVector(op_.dm, &local));
  PetscCall(VecSetBlockSize(*coordinates, op_.boundary->dim));
  PetscFunctionReturn(0);
}

PetscErrorCode HarmonicStart::SolveSystem(double omega, Mat Z, Vec rhs, Vec U) const {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)op_.dm);
  HarmonicSolver solver = op_.options->harmonic_solver;
  if (solver != HarmonicSolver::kKrylov) {
    bool fits = true;
    PetscCall(CheckFactorMemory(Z, "wave_harmonic_",
                                {"Harmonic start", "-wave_harmonic_memory_limit", op_.options->harmonic_memory_limit_gb,
                                 op_.options->harmonic_force, solver == HarmonicSolver::kAuto},
                                &fits));
    solver = fits ? HarmonicSolver::kDirect : HarmonicSolver::kKrylov;
  }
  PetscInt n_dofs;
  PetscCall(MatGetSize(Z, &n_dofs, nullptr));
  KSP ksp;
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "wave_harmonic_"));
  PetscCall(KSPSetOperators(ksp, Z, Z));
  Mat P = nullptr;
  Vec coordinates = nullptr;
  if (solver == HarmonicSolver::kDirect) {
    PC pc;
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    PetscCall(PetscPrintf(comm, "Harmonic start: factoring and solving the %" PetscInt_FMT " doubled dofs (MUMPS)\n",
                          n_dofs));
  } else {
    PetscCall(AssemblePreconditioner(omega, &P));
    PetscCall(NodePositionVector(&coordinates));
    PetscCall(ConfigureHarmonicKrylov(ksp, P, coordinates));
    PetscCall(PetscPrintf(comm, "Harmonic start: GMRES on the %" PetscInt_FMT " doubled dofs, multigrid on "
                          "K + w^2 M for each part\n", n_dofs));
  }
  PetscCall(KSPSetFromOptions(ksp));
  {
    const Heartbeat beat(comm, "Harmonic start: solving");  // minutes on a 3D box, with no word from MUMPS
    PetscCall(KSPSolve(ksp, rhs, U));
  }
  PetscCall(ReportHarmonicSolve(ksp, Z, rhs, U));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&P));
  PetscCall(VecDestroy(&coordinates));
  PetscFunctionReturn(0);
}

PetscErrorCode HarmonicStart::Solve(Vec u, Vec v) const {
  PetscFunctionBeginUser;
  const double omega = 2.0 * M_PI * op_.excitation->signal.frequency;
  Mat Z;
  Vec rhs, U;
  PetscCall(Assemble(omega, &Z, &rhs));
  PetscCall(VecDuplicate(rhs, &U));
  PetscCall(SolveSystem(omega, Z, rhs, U));
  // u(0) = Im U, v(0) = ω Re U.
  PetscScalar *pu, *pv;
  const PetscScalar* pU;
  PetscInt n;
  PetscCall(VecGetLocalSize(u, &n));
  PetscCall(VecGetArray(u, &pu));
  PetscCall(VecGetArray(v, &pv));
  PetscCall(VecGetArrayRead(U, &pU));
  for (PetscInt i = 0; i < n; ++i) pu[i] = pU[2 * i + 1], pv[i] = omega * pU[2 * i];
  PetscCall(VecRestoreArrayRead(U, &pU));
  PetscCall(VecRestoreArray(v, &pv));
  PetscCall(VecRestoreArray(u, &pu));
  PetscCall(VecDestroy(&U));
  PetscCall(VecDestroy(&rhs));
  PetscCall(MatDestroy(&Z));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::StartHarmonic() {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscCheck(!second_order_, comm, PETSC_ERR_SUP, "-wave_start harmonic: not with the implicit wave TS (alpha2)");
  const HarmonicStart start({dm_, &op_.space(), op_.stepping(), op_.mass(), &boundary_, &excitation_, &material_, &options_, interface_});
  Vec u, v;
  PetscCall(GetFields(&u, &v));
  PetscCall(start.Solve(u, v));
  PetscCall(RestoreFields(&u, &v));
  double springs;
  PetscCall(StuckSpringEnergy(&springs));
  PetscCall(BookInitialEnergy(springs));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::StuckSpringEnergy(double* springs) {
  PetscFunctionBeginUser;
  *springs = 0.0;  // ½ [u]ᵀ K_c [u] of the stuck springs, K_c by entries of this rank's cells
  if (!interface_) PetscFunctionReturn(0);
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  std::vector<PetscInt> rows, cols;
  std::vector<double> values;
  PetscCall(interface_->TangentStiffness(&rows, &cols, &values));
  Vec u, v, all;
  VecScatter to_all;
  PetscCall(GetFields(&u, &v));
  PetscCall(VecScatterCreateToAll(u, &to_all, &all));
  PetscCall(VecScatterBegin(to_all, u, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_all, u, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(RestoreFields(&u, &v));
  const PetscScalar* x;
  PetscCall(VecGetArrayRead(all, &x));
  for (std::size_t k = 0; k < rows.size(); ++k) *springs += 0.5 * values[k] * x[rows[k]] * x[cols[k]];
  PetscCall(VecRestoreArrayRead(all, &x));
  PetscCall(VecScatterDestroy(&to_all));
  PetscCall(VecDestroy(&all));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, springs, 1, MPI_DOUBLE, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::BookInitialEnergy(double interface_energy) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  WaveEnergy e;
  PetscCall(Energy(&e));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) accounted_.work_source += e.kinetic + e.strain + e.integrator + interface_energy;
  // What the terms remember of the last step's end state is this state.
  Vec u, v;
  PetscCall(GetFields(&u, &v));
  StepState state;
  PetscCall(VecGetArrayRead(u, &state.u));
  PetscCall(VecGetArrayRead(v, &state.v));
  for (auto& term : terms_) term->Resume(state);
  PetscCall(VecRestoreArrayRead(u, &state.u));
  PetscCall(VecRestoreArrayRead(v, &state.v));
  PetscCall(RestoreFields(&u, &v));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

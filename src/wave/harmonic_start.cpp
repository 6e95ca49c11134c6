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
#include <cmath>

#include "vibrotherm/util/heartbeat.hpp"
#include "vibrotherm/wave/factor_memory.hpp"
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

}  // namespace

PetscErrorCode WaveSolver::AssembleHarmonic(double omega, Mat* Z, Vec* rhs) const {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscInt n, rstart, rend;
  PetscCall(VecGetLocalSize(M_, &n));
  PetscCall(VecGetOwnershipRange(M_, &rstart, &rend));
  std::vector<PetscInt> nnz(2 * n);
  for (PetscInt g = rstart; g < rend; ++g) {
    PetscInt ncols;
    PetscCall(MatGetRow(A_, g, &ncols, nullptr, nullptr));
    nnz[2 * (g - rstart)] = nnz[2 * (g - rstart) + 1] = 2 * ncols + 16;  // K, the damping blocks, a contact cell
    PetscCall(MatRestoreRow(A_, g, &ncols, nullptr, nullptr));
  }
  PetscCall(MatCreateAIJ(comm, 2 * n, 2 * n, PETSC_DETERMINE, PETSC_DETERMINE, 0, nnz.data(), 0, nnz.data(), Z));
  PetscCall(MatSetOption(*Z, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(MatCreateVecs(*Z, nullptr, rhs));
  const PetscScalar* m;
  PetscCall(VecGetArrayRead(M_, &m));
  for (PetscInt g = rstart; g < rend; ++g) {  // K = −M A (A = −M⁻¹K), − ω² M, the damping ω α M
    const PetscInt i = g - rstart, *cols;
    const PetscScalar* values;
    PetscInt ncols;
    PetscCall(MatGetRow(A_, g, &ncols, &cols, &values));
    for (PetscInt k = 0; k < ncols; ++k) PetscCall(AddBoth(*Z, g, cols[k], -m[i] * PetscRealPart(values[k])));
    PetscCall(MatRestoreRow(A_, g, &ncols, &cols, &values));
    PetscCall(AddBoth(*Z, g, g, -omega * omega * m[i]));
    if (material_.damping_rate > 0.0) PetscCall(AddDamping(*Z, g, g, omega * material_.damping_rate * m[i]));
  }
  PetscCall(VecRestoreArrayRead(M_, &m));
  const int D = boundary_.dim;
  for (std::size_t k = 0; k < boundary_.dashpots.size(); ++k) {
    const PetscInt first = rstart + D * boundary_.dashpots.nodes[k];
    for (int p = 0; p < D; ++p)
      for (int q = 0; q < D; ++q)
        PetscCall(AddDamping(*Z, first + p, first + q, omega * boundary_.dashpots.at(k, p, q)));
  }
  if (interface_) {
    std::vector<PetscInt> rows, cols;
    std::vector<double> values;
    PetscCall(interface_->TangentStiffness(&rows, &cols, &values));
    for (std::size_t k = 0; k < rows.size(); ++k) PetscCall(AddBoth(*Z, rows[k], cols[k], values[k]));
  }
  PetscCall(MatAssemblyBegin(*Z, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*Z, MAT_FINAL_ASSEMBLY));
  if (excitation_.type == SourceType::Traction) {  // F = A · shape, a real phasor
    const PetscScalar* shape;
    PetscScalar* f;
    PetscCall(VecGetArrayRead(boundary_.traction_shape, &shape));
    PetscCall(VecGetArray(*rhs, &f));
    for (PetscInt i = 0; i < n; ++i) f[2 * i] = excitation_.signal.amplitude * shape[i];
    PetscCall(VecRestoreArray(*rhs, &f));
    PetscCall(VecRestoreArrayRead(boundary_.traction_shape, &shape));
  }
  // Constrained components: their rows and columns by the prescribed values (real A on the source's).
  std::vector<PetscInt> fixed;
  Vec known;
  PetscCall(VecDuplicate(*rhs, &known));
  for (const Constraint& c : boundary_.constraints) {
    int axis = 0;
    while (axis + 1 < D && !(std::abs(c.d[axis]) > 1.0 - 1e-12)) ++axis;
    PetscCheck(std::abs(c.d[axis]) > 1.0 - 1e-12, comm, PETSC_ERR_SUP,
               "-wave_start harmonic: a constrained direction (%g, %g, %g) is not along a coordinate axis", c.d[0],
               c.d[1], c.d[2]);
    const PetscInt g = rstart + D * c.node + axis;
    const double value = c.source ? excitation_.signal.amplitude * c.d[axis] : 0.0;
    fixed.insert(fixed.end(), {2 * g, 2 * g + 1});
    PetscCall(VecSetValue(known, 2 * g, value, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(known));
  PetscCall(VecAssemblyEnd(known));
  PetscCall(MatZeroRowsColumns(*Z, static_cast<PetscInt>(fixed.size()), fixed.data(), 1.0, known, *rhs));
  PetscCall(VecDestroy(&known));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::StartHarmonic() {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  PetscCheck(!second_order_, comm, PETSC_ERR_SUP, "-wave_start harmonic: not with the implicit wave TS (alpha2)");
  const double omega = 2.0 * M_PI * excitation_.signal.frequency;
  Mat Z;
  Vec rhs, U;
  PetscCall(AssembleHarmonic(omega, &Z, &rhs));
  PetscCall(VecDuplicate(rhs, &U));
  KSP ksp;
  PC pc;
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "wave_harmonic_"));
  PetscCall(KSPSetOperators(ksp, Z, Z));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCall(KSPSetFromOptions(ksp));
  PetscBool force = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-force", &force, nullptr));  // declared with the mesh options
  PetscCall(CheckFactorMemory(Z, "wave_harmonic_",
                              {"Harmonic start", "-wave_harmonic_memory_limit", options_.harmonic_memory_limit_gb,
                               force == PETSC_TRUE}));
  PetscInt n_dofs;
  PetscCall(MatGetSize(Z, &n_dofs, nullptr));
  PetscCall(PetscPrintf(comm, "Harmonic start: factoring and solving the %" PetscInt_FMT " doubled dofs (MUMPS)\n",
                        n_dofs));
  {
    const Heartbeat beat(comm, "Harmonic start: factoring");  // minutes on a 3D box, with no word from MUMPS
    PetscCall(KSPSolve(ksp, rhs, U));
  }
  // u(0) = Im U, v(0) = ω Re U.
  Vec u, v;
  PetscCall(GetFields(&u, &v));
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
  PetscCall(RestoreFields(&u, &v));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&U));
  PetscCall(VecDestroy(&rhs));
  PetscCall(MatDestroy(&Z));
  PetscCall(BookInitialEnergy());
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::BookInitialEnergy() {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm_);
  WaveEnergy e;
  PetscCall(Energy(&e));
  double springs = 0.0;  // ½ [u]ᵀ K_c [u] of the stuck springs, K_c by entries of this rank's cells
  if (interface_) {
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
    for (std::size_t k = 0; k < rows.size(); ++k) springs += 0.5 * values[k] * x[rows[k]] * x[cols[k]];
    PetscCall(VecRestoreArrayRead(all, &x));
    PetscCall(VecScatterDestroy(&to_all));
    PetscCall(VecDestroy(&all));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &springs, 1, MPI_DOUBLE, MPI_SUM, comm));
  }
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) accounted_.work_source += e.kinetic + e.strain + e.integrator + springs;
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

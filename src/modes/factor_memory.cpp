// The memory a -modes run's shift-invert factorisation will take, from MUMPS's own
// analysis, checked before any numerical work: a 3D stiffness fills far more than its
// matrix (nested dissection: O(n^{4/3}) entries), and running out mid-factorisation on a
// shared node is the worst way to learn it.
#include <petscmat.h>

#include <cmath>

#include "vibrotherm/mesh/memory_estimate.hpp"
#include "vibrotherm/modes/modal_analysis.hpp"

namespace vibrotherm::modes {

PetscErrorCode MumpsFactorMemory(Mat A, double* bytes) {
  PetscFunctionBeginUser;
  Mat F;
  MatFactorInfo info;
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatGetFactor(A, MATSOLVERMUMPS, MAT_FACTOR_LU, &F));
  PetscCall(MatLUFactorSymbolic(F, A, nullptr, nullptr, &info));  // MUMPS's analysis: ordering, estimates
  PetscInt megabytes;
  PetscCall(MatMumpsGetInfog(F, 17, &megabytes));  // in-core factorisation, summed over the ranks [MB]
  PetscCall(MatDestroy(&F));
  *bytes = static_cast<double>(megabytes) * 1e6;
  PetscFunctionReturn(0);
}

PetscErrorCode CheckFactorMemory(Mat A, const ModesOptions& options) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)A);
  double needed;
  PetscCall(MumpsFactorMemory(A, &needed));
  double limit = options.memory_limit_gb * 1e9;
  if (!(limit > 0.0)) {
    limit = mesh::AvailableMemory();
    PetscCallMPI(MPI_Bcast(&limit, 1, MPI_DOUBLE, 0, comm));
    limit *= 0.9;
  }
  PetscInt dofs;
  PetscCall(MatGetSize(A, &dofs, nullptr));
  PetscCall(PetscPrintf(comm, "Modes: MUMPS estimates %.3g GB for the factorisation of %" PetscInt_FMT
                        " dofs (limit %.3g GB)\n", needed / 1e9, dofs, limit / 1e9));
  PetscCheck(options.force || !(limit > 0.0) || needed <= limit, comm, PETSC_ERR_USER_INPUT,
             "-modes: MUMPS estimates %.3g GB for the factorisation of %" PetscInt_FMT " dofs, more than the "
             "%.3g GB allowed (-modes_memory_limit, default 0.9 x the memory available): coarsen -mesh_h, or "
             "give -force",
             needed / 1e9, dofs, limit / 1e9);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::modes

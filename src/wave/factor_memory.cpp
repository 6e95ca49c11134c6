// MUMPS's memory estimate, checked (factor_memory.hpp). The estimate is a lower bound of
// the run's memory (not counting the matrices, a Krylov basis, pivoting growth) and
// costs one extra analysis (the ordering); the limit is rank 0's node's.
#include <petscmat.h>

#include <cmath>
#include <string>

#include "vibrotherm/mesh/memory_estimate.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/heartbeat.hpp"
#include "vibrotherm/wave/factor_memory.hpp"

namespace vibrotherm::wave {

PetscErrorCode MumpsFactorMemory(Mat A, const char* prefix, double* bytes) {
  PetscFunctionBeginUser;
  Mat F;
  MatFactorInfo info;
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatGetFactor(A, MATSOLVERMUMPS, MAT_FACTOR_LU, &F));
  PetscCall(MatSetOptionsPrefix(F, prefix));  // the user's -<prefix>mat_mumps_icntl_* (ordering, relaxation) count
  PetscCall(MatLUFactorSymbolic(F, A, nullptr, nullptr, &info));  // MUMPS's analysis: ordering, estimates
  MatFactorError failed;
  PetscCall(MatFactorGetError(F, &failed));
  PetscInt megabytes = -1;
  if (failed == MAT_FACTOR_NOERROR) PetscCall(MatMumpsGetInfog(F, 17, &megabytes));  // in-core, summed over ranks [MB]
  PetscCall(MatDestroy(&F));
  PetscCheck(megabytes >= 0, PetscObjectComm((PetscObject)A), PETSC_ERR_LIB,
             "MUMPS's analysis (%s) failed (error %d)", prefix, static_cast<int>(failed));
  *bytes = static_cast<double>(megabytes) * 1e6;
  PetscFunctionReturn(0);
}

PetscErrorCode CheckFactorMemory(Mat A, const char* prefix, const FactorMemoryLimit& options, bool* fits) {
  PetscFunctionBeginUser;
  if (fits) *fits = true;
  MPI_Comm comm = PetscObjectComm((PetscObject)A);
  std::string solver = MATSOLVERMUMPS;
  PetscCall(OptionText(prefix, "-pc_factor_mat_solver_type", &solver));
  if (solver != MATSOLVERMUMPS) PetscFunctionReturn(0);  // another solver: no MUMPS estimate
  double needed;
  {
    const Heartbeat beat(comm, std::string(options.who) + ": MUMPS's analysis (its memory estimate)");
    PetscCall(MumpsFactorMemory(A, prefix, &needed));
  }
  double limit = options.limit_gb * 1e9;
  if (!(limit > 0.0)) {
    limit = mesh::AvailableMemory();
    PetscCallMPI(MPI_Bcast(&limit, 1, MPI_DOUBLE, 0, comm));
    limit *= 0.9;
  }
  PetscInt dofs;
  PetscCall(MatGetSize(A, &dofs, nullptr));
  PetscCall(PetscPrintf(comm, "%s: MUMPS estimates %.3g GB for the factorisation of %" PetscInt_FMT
                        " dofs (limit %.3g GB)\n", options.who, needed / 1e9, dofs, limit / 1e9));
  if (options.fallback && !options.force && limit > 0.0 && needed > limit) {
    PetscCall(PetscPrintf(comm, "%s: that is more than the %.3g GB allowed (%s): an iterative solve instead\n",
                          options.who, limit / 1e9, options.option));
    if (fits) *fits = false;
    PetscFunctionReturn(0);
  }
  PetscCheck(options.force || !(limit > 0.0) || needed <= limit, comm, PETSC_ERR_USER_INPUT,
             "%s: MUMPS estimates %.3g GB for the factorisation of %" PetscInt_FMT " dofs, more than the "
             "%.3g GB allowed (%s, default 0.9 x the memory available): coarsen -mesh_h, or give -force",
             options.who, needed / 1e9, dofs, limit / 1e9, options.option);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave

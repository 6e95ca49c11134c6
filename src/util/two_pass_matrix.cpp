#include "vibrotherm/util/two_pass_matrix.hpp"

namespace vibrotherm::util {

PetscErrorCode CreateTwoPassMatrices(MPI_Comm comm, PetscInt rows, PetscInt cols, PetscInt global_rows,
                                     PetscInt global_cols, Mat* pattern, Mat* matrix) {
  PetscFunctionBeginUser;
  PetscCall(MatCreate(comm, pattern));
  PetscCall(MatSetType(*pattern, MATPREALLOCATOR));
  PetscCall(MatSetSizes(*pattern, rows, cols, global_rows, global_cols));
  PetscCall(MatSetUp(*pattern));
  PetscCall(MatCreate(comm, matrix));
  PetscCall(MatSetType(*matrix, MATAIJ));
  PetscCall(MatSetSizes(*matrix, rows, cols, global_rows, global_cols));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::util

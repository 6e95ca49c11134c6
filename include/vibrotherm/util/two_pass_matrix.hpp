#pragma once
// A sparse matrix assembled in two passes: first the pattern into a MATPREALLOCATOR, then the
// values into a MATAIJ preallocated exactly from it. For transfers whose rows meet hundreds
// of columns (a heat node beside a crack, a 3D heat row over Q2 wave cells), where
// reallocating rows during insertion took minutes.
#include <petscmat.h>

namespace vibrotherm::util {

/// The empty preallocator `pattern` and the AIJ `matrix` of the same sizes. Insert the same
/// entries into both (pattern first, any values), call MatPreallocatorPreallocate(pattern,
/// PETSC_TRUE, matrix) between the passes, and destroy `pattern` after. Collective.
PetscErrorCode CreateTwoPassMatrices(MPI_Comm comm, PetscInt rows, PetscInt cols, PetscInt global_rows,
                                     PetscInt global_cols, Mat* pattern, Mat* matrix);

}  // namespace vibrotherm::util

#include "vibrotherm/fe/cell_matrix.hpp"

#include <vector>

namespace vibrotherm::fe {

PetscErrorCode CreateCellMatrix(const LagrangeSpace& space, const std::function<bool(std::size_t)>& include, Mat* A) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  PetscCall(DMSetMatrixPreallocateSkip(dm, PETSC_TRUE));  // sizes, type, block size and map only
  PetscCall(DMCreateMatrix(dm, A));
  PetscCall(DMSetMatrixPreallocateSkip(dm, PETSC_FALSE));
  PetscInt m, n, M, N;
  PetscCall(MatGetLocalSize(*A, &m, &n));
  PetscCall(MatGetSize(*A, &M, &N));
  Mat pattern;
  PetscCall(MatCreate(PetscObjectComm((PetscObject)dm), &pattern));
  PetscCall(MatSetType(pattern, MATPREALLOCATOR));
  PetscCall(MatSetSizes(pattern, m, n, M, N));
  PetscCall(MatSetBlockSizesFromMats(pattern, *A, *A));
  PetscCall(MatSetUp(pattern));
  PetscSection local, global;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  const std::size_t closure = static_cast<std::size_t>(space.nodes_per_cell()) * space.components();
  const std::vector<PetscScalar> zeros(closure * closure, 0.0);
  for (std::size_t k = 0; k < space.cells().size(); ++k)
    if (!include || include(k))
      PetscCall(DMPlexMatSetClosure(dm, local, global, pattern, space.cells()[k], zeros.data(), INSERT_VALUES));
  PetscCall(MatAssemblyBegin(pattern, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(pattern, MAT_FINAL_ASSEMBLY));
  PetscCall(MatPreallocatorPreallocate(pattern, PETSC_TRUE, *A));
  PetscCall(MatDestroy(&pattern));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::fe

// Splitting the cracks with cohesive cells (PETSC-NOTES.md, "Crack split").
#pragma once

#include <petscdmplex.h>

namespace vibrotherm::mesh {

/// Splits every crack of the serial mesh (faces of label `crack`, tips of label
/// `crack_tip` kept whole) into + and − faces joined by cohesive cells
/// (DM_POLYTOPE_SEG_PRISM_TENSOR, numbered after the bulk cells). All labels
/// are carried onto the new points. A mesh without cracks is copied as is.
/// It labels crack_plus the + face of each cohesive cell (labels.hpp), in both dimensions.
PetscErrorCode SplitCracks(DM serial, DM* split);

/// Which face of a cohesive cell is + (0: its cone[0], 1: its cone[1]), by the
/// crack_plus label SplitCracks set (carried by distribution).
PetscErrorCode PlusSide(DM split, PetscInt cohesive, int* plus);

}  // namespace vibrotherm::mesh

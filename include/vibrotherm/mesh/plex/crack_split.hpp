// Splitting the cracks with cohesive cells (PETSC-NOTES.md, "Crack split").
#pragma once

#include <petscdmplex.h>

namespace vibrotherm::mesh {

/// Splits every crack of the serial mesh (faces of label `crack`, tips of label
/// `crack_tip` kept whole) into + and − faces joined by cohesive cells
/// (DM_POLYTOPE_SEG_PRISM_TENSOR, numbered after the bulk cells). All labels
/// are carried onto the new points. A mesh without cracks is copied as is.
PetscErrorCode SplitCracks(DM serial, DM* split);

}  // namespace vibrotherm::mesh

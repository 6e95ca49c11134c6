// A 3D box specimen (-specimen_depth > 0): the graded hexahedral grid with its
// buried crack (box_grid.hpp, box_mesher.hpp), split serially with the crack front
// in the boundary label (one cohesive cell per crack face, checked), distributed.
// Waves only for now: the specimen has no heat mesh (heat null) and no crack
// surface gathers (wave_cracks, heat_cracks empty: they are 2D).
#pragma once

#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::mesh {

/// geometry: checked by ReadSpecimenGeometry (depth > 0). Collective.
PetscErrorCode CreateBoxSpecimen(MPI_Comm comm, const SpecimenGeometry& geometry, Specimen* specimen);

}  // namespace vibrotherm::mesh

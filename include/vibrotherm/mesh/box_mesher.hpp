// The serial DMPlex of a 3D box specimen: PETSc's structured hexahedra on rank 0,
// moved onto the graded, sheared grid of box_grid.hpp, with the labels of
// labels.hpp (the crack's faces with their crack_face ids, an empty crack_tip:
// the splitter finds the 3D front itself; the outer faces by kind and side:
// side 0..3 as in 2D, 4 front (z = depth), 5 back (z = 0)).
#pragma once

#include <petscdmplex.h>

#include "vibrotherm/mesh/box_grid.hpp"

namespace vibrotherm::mesh {

/// Collective; every cell lives on rank 0 (split it, then distribute). *crack_faces: the crack's faces.
PetscErrorCode CreateBoxPlex(MPI_Comm comm, const SpecimenGeometry& geometry, const BoxGrid& grid, DM* dm,
                             PetscInt* crack_faces);

/// The faces of the transducer patch (-source_patch_edge) labelled source instead of
/// their face's kind; after the vertices moved (the test is in physical coordinates).
PetscErrorCode LabelBoxPatch(DM dm, const SpecimenGeometry& geometry);

}  // namespace vibrotherm::mesh

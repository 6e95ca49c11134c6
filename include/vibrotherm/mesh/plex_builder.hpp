// Serial DMPlex from MeshData (all cells on rank 0), its labels, and the crack
// facet numbering that must follow any refinement.
#pragma once

#include <petscdmplex.h>

#include <string>
#include <vector>

#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh {

/// Creates the interpolated serial DMPlex with the edge labels of labels.hpp
/// (crack, side, sink and one label per EdgeKind). Collective; rank 0 holds the mesh.
PetscErrorCode CreateSerialPlex(MPI_Comm comm, const MeshData& mesh, DM* dm);

/// Numbers the crack faces (label crack_face) by walking each crack from one
/// end, and labels the tips: crack ends on no outer face. Call after refinement.
/// Errors for a crack that is not a simple open polyline.
PetscErrorCode LabelCrackFacetsAndTips(DM dm, const std::vector<std::string>& crack_names);

}  // namespace vibrotherm::mesh

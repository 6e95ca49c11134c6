// The specimen's two distributed meshes, built from the options:
//   wave  the crack-split mesh (cohesive cells), for elastodynamics
//   heat  the unsplit mesh (temperature is continuous across cracks)
// Both carry the labels of labels.hpp; crack facets match through crack_face.
#pragma once

#include <petscdmplex.h>

#include <string>
#include <vector>

#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

struct CrackInfo {
  std::string name;
  double requested_length = 0.0;  ///< from the options (0 for a mesh file)
};

struct Specimen {
  DM wave = nullptr;
  DM heat = nullptr;
  std::vector<CrackInfo> cracks;
  std::string source;  ///< "generated" or the mesh file
};

/// Reads -mesh_file or the generated-specimen options (-specimen_*, -crack_*,
/// -mesh_*, -edge_*), meshes, refines (-dm_refine), splits and distributes
/// (-petscpartitioner_type, metis registered). Collective.
PetscErrorCode SpecimenCreate(MPI_Comm comm, Specimen* specimen);
PetscErrorCode SpecimenDestroy(Specimen* specimen);

/// Reads the generated-specimen options into geometry (used by SpecimenCreate).
PetscErrorCode ReadSpecimenGeometry(MPI_Comm comm, SpecimenGeometry* geometry);

}  // namespace vibrotherm::mesh

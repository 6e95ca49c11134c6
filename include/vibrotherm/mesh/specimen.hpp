// The specimen's two distributed meshes, built from the options:
//   wave  the crack-split mesh (cohesive cells), for elastodynamics
//   heat  an unsplit mesh (temperature is continuous across cracks): by default
//         its own mesh graded to the cracks (heat_mesh.hpp), partitioned on its
//         own; -heat_mesh wave reuses the unsplit wave mesh; for -mesh_file
//         scenes -heat_mesh_file gives it (else the unsplit wave mesh)
// Both carry the labels of labels.hpp. Crack facets are numbered (crack_face)
// along each crack from the end with the smaller x (then y): ξ = 0 there on both.
#pragma once

#include <petscdmplex.h>

#include <optional>
#include <string>
#include <vector>

#include "vibrotherm/mesh/crack_surface.hpp"
#include "vibrotherm/mesh/heat_mesh.hpp"
#include "vibrotherm/mesh/plex/lts_partition.hpp"
#include "vibrotherm/mesh/plex/point_origin.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"
#include "vibrotherm/mesh/specimen_options.hpp"

namespace vibrotherm::mesh {

struct CrackInfo {
  std::string name;
  double requested_length = 0.0;  ///< from the options (0 for a mesh file)
  /// A generated 3D box: the faces the crack breaks (side names; empty: buried). Unknown
  /// (not written) for other specimens.
  std::optional<std::vector<std::string>> breaks;
};

struct Specimen {
  DM wave = nullptr;
  DM heat = nullptr;
  std::vector<CrackInfo> cracks;
  std::string source;  ///< "generated" or the mesh file
  std::string heat_source;  ///< "graded", "wave" (the unsplit wave mesh) or the heat mesh file
  PointOrigin wave_origin, heat_origin;  ///< serial point of each local point (checkpoint keys)
  CrackSurface wave_cracks, heat_cracks;  ///< the cracks of each mesh, gathered once
  /// Equal parts per reference direction of a wave crack face in the friction heat's
  /// quadrature. 2D: 1 (the faces are cut at the heat mesh's crack vertices, exact);
  /// the 3D box chooses them so that they include the heat grid's lines on the crack
  /// (exact), a 3D mesh file takes 16 (accurate).
  int crack_face_subdivisions = 1;
};

/// Meshes what the specimen options describe (-mesh_file, or the generated specimen),
/// refines (-dm_refine), splits and distributes (-petscpartitioner_type, metis registered);
/// the heat mesh from the -heat_mesh* options. `exchange_length` = √(α · heat step), the
/// layer friction heats in one exchange: the default first heat layer is half of it.
/// lts: the wave's local-time-stepping options, for the partition's weights
/// (lts_partition.hpp). Collective.
PetscErrorCode SpecimenCreate(MPI_Comm comm, const SpecimenOptions& options, double exchange_length,
                              Specimen* specimen, const LtsWeighting& lts = {});
PetscErrorCode SpecimenDestroy(Specimen* specimen);

/// Prints the memory estimate of a generated specimen (memory_estimate.hpp) and
/// refuses, naming the options, one beyond the memory available unless -force.
PetscErrorCode CheckSpecimenMemory(MPI_Comm comm, const SpecimenOptions& options, PetscInt wave_degree,
                                   double exchange_length);

}  // namespace vibrotherm::mesh

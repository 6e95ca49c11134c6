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
  /// 3D: sub-squares per side of a wave crack face in the friction heat's quadrature,
  /// chosen so that their edges include the heat grid's lines on the crack (exact).
  int crack_face_subdivisions = 4;
};

/// Reads -mesh_file or the generated-specimen options (-specimen_*, -crack_*,
/// -mesh_*, -edge_*), meshes, refines (-dm_refine), splits and distributes
/// (-petscpartitioner_type, metis registered); the heat mesh from the
/// -heat_mesh* options. `exchange_length` = √(α · coupling interval), the
/// layer friction heats in one exchange: the default first heat layer is half
/// of it. Collective.
/// lts: the wave's local-time-stepping options, for the partition's weights (lts_partition.hpp).
PetscErrorCode SpecimenCreate(MPI_Comm comm, double exchange_length, Specimen* specimen,
                              const LtsWeighting& lts = {});
PetscErrorCode SpecimenDestroy(Specimen* specimen);

/// Reads (declares, for -help and the check of the command line before meshing)
/// every mesh option and checks the values without building anything; with
/// -mesh_file, the generated-specimen options given are noted as ignored (the
/// file sets the specimen) instead of checked. Collective.
PetscErrorCode DeclareSpecimenOptions(MPI_Comm comm, double exchange_length);
/// Prints the memory estimate of a generated specimen (memory_estimate.hpp) and
/// refuses, naming the options, one beyond the memory available unless -force.
PetscErrorCode CheckSpecimenMemory(MPI_Comm comm, PetscInt wave_degree, double exchange_length);

/// The finest wave element edge the options ask for before meshing [m]: the least of
/// -mesh_h and -mesh_h_crack, halved per -dm_refine; 0 for a -mesh_file (known once read).
PetscErrorCode FinestRequestedElement(MPI_Comm comm, double* h);

/// Reads the generated-specimen options into geometry (used by SpecimenCreate);
/// check: refuse a specimen that cannot be meshed (false: declare them only).
PetscErrorCode ReadSpecimenGeometry(MPI_Comm comm, SpecimenGeometry* geometry, bool check = true);
/// Reads -heat_mesh, -heat_mesh_h_crack, -heat_mesh_growth, -heat_mesh_h_along,
/// -heat_mesh_h (defaults from the wave mesh sizes and exchange_length, each
/// capped by the next size); check: refuse sizes that do not nest.
PetscErrorCode ReadHeatMeshSizes(MPI_Comm comm, const SpecimenGeometry& geometry, double exchange_length,
                                 HeatMeshSizes* sizes, bool check = true);

}  // namespace vibrotherm::mesh

// The specimen's options, read once (into coupling::Scene) and handed to whatever builds
// or sizes the specimen: where the mesh comes from (-mesh_file, -heat_mesh_file,
// -dm_refine, -force), the generated specimen (-specimen_*, -crack_*, -mesh_*, -edge_*,
// -source_patch_*) and the heat mesh (-heat_mesh*).
#pragma once

#include <petscsys.h>

#include <optional>
#include <string>
#include <vector>

#include "vibrotherm/mesh/heat_mesh.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::mesh {

/// Where the meshes come from.
struct MeshSource {
  std::string file, heat_file;  ///< -mesh_file, -heat_mesh_file
  bool from_file = false, heat_from_file = false;
  int file_dimension = 0;    ///< the -mesh_file's dimension when the scene read it (0: not yet, SpecimenCreate reads it)
  PetscInt refinements = 0;  ///< -dm_refine
  bool force = false;        ///< -force: run even above the memory estimate
};

/// The -heat_mesh* options as given; a size not given follows the specimen (HeatMeshSizesFor).
struct HeatMeshOptions {
  bool graded = true;  ///< -heat_mesh graded|wave
  std::optional<double> h_crack, growth, h_along, h, grading;
};

enum class MeshCell { Quad, Triangle };  ///< -mesh_cell quad|tri

/// The generated specimen's options as typed: the per-crack lists become the geometry's
/// cracks once checked against each other.
struct SpecimenGeometryInput {
  SpecimenGeometry geometry;
  MeshCell cell = MeshCell::Quad;
  std::vector<double> centers, lengths, angles, widths, tilts;  ///< -crack_center, _length, _angle, _width, _tilt
  std::vector<PetscInt> shapes;                                 ///< -crack_shape (CrackShape indices)
};
/// -specimen_*, -crack_* of the geometry, -mesh_h*, -mesh_grading, -mesh_cell, -mesh_crack_mirror,
/// -edge_*, -source_patch_*, declared (option_spec.hpp).
const std::vector<OptionSpec<SpecimenGeometryInput>>& SpecimenGeometryOptionSpecs();

/// -mesh_file, -heat_mesh_file, -dm_refine, -force, declared.
const std::vector<OptionSpec<MeshSource>>& MeshSourceOptionSpecs();

/// The -heat_mesh* options with the sizes -help shows (the defaults for this geometry).
struct HeatMeshInput {
  HeatMeshOptions options;
  HeatMeshSizes shown;
};
/// -heat_mesh and -heat_mesh_h_crack, _growth, _h_along, _h, _grading, declared.
const std::vector<OptionSpec<HeatMeshInput>>& HeatMeshOptionSpecs();

struct SpecimenOptions {
  MeshSource source;
  /// The generated specimen's options (with -mesh_file: as given, unchecked; the file sets the specimen).
  SpecimenGeometry geometry;
  HeatMeshOptions heat;
};

/// Reads (and declares, for -help and the check of the command line before meshing) every
/// specimen option, checking the values without building anything; with -mesh_file the
/// generated-specimen options given are noted as ignored instead of checked. exchange_length:
/// √(α · heat step), the layer friction heats in one exchange (the heat mesh's default first
/// layer is half of it). Collective.
PetscErrorCode ReadSpecimenOptions(MPI_Comm comm, double exchange_length, SpecimenOptions* options, OptionValues* values = nullptr);

/// The heat mesh's sizes for a specimen of this geometry: defaults from the physics (the first
/// layer resolves the layer one exchange heats; layers grow to the wave mesh's crack spacing / 2),
/// each capped by the next size, then the sizes given.
HeatMeshSizes HeatMeshSizesFor(const HeatMeshOptions& options, const SpecimenGeometry& geometry,
                               double exchange_length);

/// The finest wave element edge the options ask for before meshing [m]: the least of
/// -mesh_h and -mesh_h_crack, halved per -dm_refine; 0 for a -mesh_file (known once read).
double FinestRequestedElement(const SpecimenOptions& options);

}  // namespace vibrotherm::mesh

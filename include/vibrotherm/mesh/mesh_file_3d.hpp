// A 3D -mesh_file: a gmsh mesh of hexahedra (8-node, gmsh type 5) whose physical
// surfaces name
//   crack1, crack2, ...  interior faces, each group one crack (split like the box's);
//   source, absorbing, free, roller, antisymmetric, fixed  the outer faces' kinds (an
//                        outer face in none is free);
//   sink                 the outer faces that are heat sinks (default: every outer face).
// Outer faces on the bounding box's planes get the `side` label of the box's faces
// (bottom y = min … back z = min), so -heat_bc_<side> and -camera_face work as for a
// generated box. The heat mesh is the file's mesh unsplit, or -heat_mesh_file (the same
// physical names).
#pragma once

#include <petscdm.h>

#include <string>

#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::mesh {

/// The dimension of a -mesh_file's mesh (2 or 3), read on rank 0; a file that cannot be
/// read is refused naming -mesh_file and the file. Collective.
PetscErrorCode MeshFileDimension(MPI_Comm comm, const std::string& path, int* dimension);

/// The specimen of a 3D mesh file, one of SpecimenCreate's sources: the wave mesh serial and
/// unsplit in *serial; heat_file's mesh in s->heat when heat_file is not empty (else none: the
/// wave mesh unsplit). Collective.
PetscErrorCode CreateMeshFileSpecimen3D(MPI_Comm comm, const std::string& file, const std::string& heat_file,
                                        DM* serial, Specimen* s);

}  // namespace vibrotherm::mesh

// A gmsh geometry script (.geo) given as -mesh_file or -heat_mesh_file: vibrotherm meshes it
// itself (gmsh's library, rank 0, in the script's own dimension and with its own mesh
// settings) into a .msh in the output directory, which the run then reads as any mesh
// file. A user needs no gmsh program, and the mesh used stays beside the results.
// Trusted input, as an options file: a script's own `Exit;` ends the process (gmsh's).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/mesh/specimen_options.hpp"

namespace vibrotherm::mesh {

/// Whether path names a gmsh geometry script (ends in .geo).
bool IsGeometryScript(const std::string& path);

/// The mesh source with each .geo (-mesh_file, -heat_mesh_file) replaced by its mesh, written
/// into `directory` under the script's name: NAME.msh and (the heat's) NAME.heat.msh. Each path
/// is added to *written before it is meshed, so that a caller can remove it even when this fails.
/// Collective.
PetscErrorCode MeshGeometryScripts(MPI_Comm comm, const std::string& directory, MeshSource* source,
                                   std::vector<std::string>* written);

}  // namespace vibrotherm::mesh

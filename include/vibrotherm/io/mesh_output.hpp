// mesh.h5 (PETSc HDF5/XDMF layout) + mesh.xmf for ParaView, written atomically.
#pragma once

#include <petscdm.h>

#include <string>

namespace vibrotherm::io {

/// Writes dm to `h5_path` and an XDMF index next to it (same stem, .xmf): the
/// bulk cells as grid "specimen" and, on a split mesh, the cohesive cells as
/// grid "cracks". Both files appear only when complete. Collective.
PetscErrorCode WriteMesh(DM dm, const std::string& h5_path);

}  // namespace vibrotherm::io

// mesh.h5 + mesh.xmf: the simulation's meshes for ParaView, written atomically.
#pragma once

#include <petscdm.h>

#include <string>
#include <utility>
#include <vector>

namespace vibrotherm::io {

/// Writes each (name, DM) to `h5_path` as grid /<name> (geometry, bulk cells)
/// and the cohesive cells of a split DM as grid "cracks" (2-node lines on that
/// DM's vertices), plus an XDMF index next to it (same stem, .xmf) holding the
/// grids as one spatial collection: ParaView's "Xdmf3 Reader T" or "XDMF
/// Reader" shows them as named blocks. Both files appear only when complete.
/// At most one DM may be split. Collective on the DMs' communicator.
PetscErrorCode WriteMeshes(const std::vector<std::pair<std::string, DM>>& meshes, const std::string& h5_path);

}  // namespace vibrotherm::io

#include "vibrotherm/io/mesh_output.hpp"

#include "vibrotherm/io/field_output.hpp"

namespace vibrotherm::io {

PetscErrorCode WriteMeshes(const std::vector<std::pair<std::string, DM>>& meshes, const std::string& h5_path) {
  PetscFunctionBeginUser;
  if (meshes.empty()) PetscFunctionReturn(0);
  FieldFile file;
  PetscCall(file.Open(PetscObjectComm((PetscObject)meshes[0].second), h5_path, XdmfLayout::kStaticGrids));
  for (const auto& [name, dm] : meshes) {
    PetscCall(file.AddMesh(name, dm));
    PetscCall(file.AddCohesiveCells("cracks", name));  // adds nothing on an unsplit mesh
  }
  PetscCall(file.Finish());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

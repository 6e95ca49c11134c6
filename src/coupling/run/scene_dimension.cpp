#include "vibrotherm/coupling/run/scene_dimension.hpp"

#include "vibrotherm/mesh/mesh_file_3d.hpp"
#include "vibrotherm/options/query/option_query.hpp"

#include <string>
#include <utility>

namespace vibrotherm::coupling {

PetscErrorCode ReadSceneDimension(MPI_Comm comm, int* dimension, int* file_dimension) {
  PetscFunctionBeginUser;
  double depth = 0.0;
  std::string file;
  bool from_file = false;
  PetscCall(OptionReal(nullptr, "-specimen_depth", &depth));
  PetscCall(OptionText(nullptr, "-mesh_file", &file, &from_file));
  *dimension = depth > 0.0 ? 3 : 2;
  *file_dimension = 0;
  if (from_file && !file.empty()) PetscCall(mesh::MeshFileDimension(comm, file, file_dimension));
  if (*file_dimension) *dimension = *file_dimension == 3 ? 3 : 2;  // the file decides
  PetscFunctionReturn(0);
}

PetscErrorCode RestrictToDimension(MPI_Comm comm, Scene* s) {
  PetscFunctionBeginUser;
  const char* given = nullptr;
  if (s->run.dimension != 3) {
    PetscCall(FirstOptionGiven({"-heat_bc_front", "-heat_bc_back", "-camera_face"}, &given));
    PetscCheck(!given, comm, PETSC_ERR_USER_INPUT, "%s applies to a 3D specimen only (-specimen_depth > 0, or a 3D "
               "-mesh_file)", given);
    PetscFunctionReturn(0);
  }
  PetscCall(FirstOptionGiven({"-crack_probe", "-crack_probe_crack"}, &given));
  PetscCheck(!given, comm, PETSC_ERR_USER_INPUT, "%s is not supported in 3D yet", given);
  std::string type = "velocityverlet", cell = "quad";
  PetscInt refine = 0;
  PetscCall(OptionText("wave_", "-ts_type", &type));
  PetscCall(OptionText(nullptr, "-mesh_cell", &cell));
  PetscCall(OptionInt(nullptr, "-dm_refine", &refine));
  PetscCheck(type != "alpha2", comm, PETSC_ERR_USER_INPUT,
             "-wave_ts_type alpha2 is not supported in 3D yet (explicit steppers only)");
  PetscCheck(cell == "quad", comm, PETSC_ERR_USER_INPUT,
             "-mesh_cell %s: a 3D box is meshed with hexahedra only (tetrahedra need a mass-lumped P2 element)", cell.c_str());
  PetscCheck(refine == 0, comm, PETSC_ERR_USER_INPUT, "-dm_refine is not supported in 3D yet: refine with -mesh_h");
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling

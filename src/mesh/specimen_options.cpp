// -specimen_*, -crack_*, -mesh_*, -edge_* options → SpecimenGeometry.
#include <string>
#include <vector>

#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::mesh {
namespace {

PetscErrorCode ReadEdgeKind(MPI_Comm comm, PetscOptionItems* PetscOptionsObject, Side side, EdgeKind* kind) {
  PetscFunctionBeginUser;
  char option[32], current[32];
  PetscCall(PetscSNPrintf(option, sizeof(option), "-edge_%s", to_string(side)));
  PetscCall(PetscStrncpy(current, to_string(*kind), sizeof(current)));
  const std::string help = "Mechanical kind of this outer edge: " + edge_kind_names();
  char value[64];
  PetscBool set;
  PetscCall(PetscOptionsString(option, help.c_str(), nullptr, current, value, sizeof(value), &set));
  if (!set) PetscFunctionReturn(0);
  for (EdgeKind k : all_edge_kinds()) {
    if (std::string(value) == to_string(k)) {
      *kind = k;
      PetscFunctionReturn(0);
    }
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: unknown value '%s' (known: %s)", option, value, edge_kind_names().c_str());
}

}  // namespace

PetscErrorCode ReadSpecimenGeometry(MPI_Comm comm, SpecimenGeometry* g) {
  PetscFunctionBeginUser;
  PetscReal centers[64], lengths[32], angles[32];
  PetscInt ncenters = 64, nlengths = 32, nangles = 32;
  PetscBool has_centers = PETSC_FALSE, has_lengths = PETSC_FALSE, has_angles = PETSC_FALSE;
  char cell[16] = "quad";
  PetscOptionsBegin(comm, nullptr, "Generated specimen (used unless -mesh_file)", nullptr);
  PetscCall(PetscOptionsReal("-specimen_width", "Width [m]", nullptr, g->width, &g->width, nullptr));
  PetscCall(PetscOptionsReal("-specimen_height", "Height [m]", nullptr, g->height, &g->height, nullptr));
  PetscCall(PetscOptionsRealArray("-crack_center", "Crack centres x1,y1,x2,y2,... [m] (origin bottom-left, y up)",
                                  nullptr, centers, &ncenters, &has_centers));
  PetscCall(PetscOptionsRealArray("-crack_length", "Crack lengths [m] (one value applies to all)", nullptr, lengths,
                                  &nlengths, &has_lengths));
  PetscCall(PetscOptionsRealArray("-crack_angle", "Crack angles to the horizontal [deg] (one value applies to all)",
                                  nullptr, angles, &nangles, &has_angles));
  PetscCall(PetscOptionsReal("-mesh_h", "Element size away from the cracks [m]", nullptr, g->h, &g->h, nullptr));
  PetscCall(PetscOptionsReal("-mesh_h_crack", "Element size along the cracks [m]", nullptr, g->h_crack, &g->h_crack,
                             nullptr));
  PetscCall(PetscOptionsReal("-mesh_grading", "Element size growth per metre of distance from a crack", nullptr,
                             g->grading, &g->grading, nullptr));
  PetscCall(PetscOptionsString("-mesh_cell", "Cell type: quad|tri", nullptr, cell, cell, sizeof(cell), nullptr));
  for (Side side : {Side::Bottom, Side::Right, Side::Top, Side::Left})
    PetscCall(ReadEdgeKind(comm, PetscOptionsObject, side, &g->edges[static_cast<int>(side)]));
  PetscOptionsEnd();

  const std::string cell_type(cell);
  PetscCheck(cell_type == "quad" || cell_type == "tri", comm, PETSC_ERR_USER_INPUT,
             "-mesh_cell: unknown value '%s' (known: quad|tri)", cell);
  g->quads = cell_type == "quad";
  if (!has_centers) ncenters = 0;
  PetscCheck(ncenters % 2 == 0, comm, PETSC_ERR_USER_INPUT, "-crack_center needs x,y pairs (got %" PetscInt_FMT " values)",
             ncenters);
  const PetscInt ncracks = ncenters / 2;
  PetscCheck(ncracks == 0 || has_lengths, comm, PETSC_ERR_USER_INPUT, "-crack_length is required with -crack_center");
  PetscCheck(ncracks > 0 || (!has_lengths && !has_angles), comm, PETSC_ERR_USER_INPUT,
             "-crack_length/-crack_angle given without -crack_center");
  if (!has_angles) nangles = 0;
  PetscCheck(nlengths == 1 || nlengths == ncracks || ncracks == 0, comm, PETSC_ERR_USER_INPUT,
             "-crack_length: %" PetscInt_FMT " values for %" PetscInt_FMT " cracks", nlengths, ncracks);
  PetscCheck(nangles <= 1 || nangles == ncracks, comm, PETSC_ERR_USER_INPUT,
             "-crack_angle: %" PetscInt_FMT " values for %" PetscInt_FMT " cracks", nangles, ncracks);
  g->cracks.clear();
  for (PetscInt i = 0; i < ncracks; ++i) {
    Crack c;
    c.x = centers[2 * i];
    c.y = centers[2 * i + 1];
    c.length = lengths[nlengths == 1 ? 0 : i];
    c.angle_deg = nangles == 0 ? 0.0 : angles[nangles == 1 ? 0 : i];
    g->cracks.push_back(c);
  }
  VibrothermCallCpp(comm, g->validate());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

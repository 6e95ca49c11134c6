// The transducer patch on a face of a 3D box, in its labels: the faces whose
// centroid lies in the patch become `source`, the rest of that face keeps its kind.
// The grid puts nodes on the patch's bounds (box_patch_grid.cpp), so the labelled
// faces are the requested rectangle exactly, except where a bound stayed on a fixed
// grid line nearby, and along the sheared axis of the front and back faces of an
// inclined crack (there the rule rounds to whole faces).
#include "vibrotherm/mesh/box_mesher.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {

PetscErrorCode LabelBoxPatch(DM dm, const SpecimenGeometry& g) {
  PetscFunctionBeginUser;
  if (!g.patch.on) PetscFunctionReturn(0);
  std::vector<PetscInt> faces;
  PetscCall(StratumPoints(dm, labels::side, static_cast<PetscInt>(g.patch.side), &faces));
  const char* rest = to_string(g.face_kind(g.patch.side));
  const auto axes = face_axes(g.patch.side);
  for (PetscInt f : faces) {
    PetscReal area, c[3], normal[3];
    PetscCall(DMPlexComputeCellGeometryFVM(dm, f, &area, c, normal));
    bool inside = true;
    for (int k = 0; k < 2; ++k) {
      const auto b = g.patch.bounds(k);
      inside = inside && c[axes[k]] > b[0] && c[axes[k]] < b[1];
    }
    if (!inside) continue;
    PetscCall(DMClearLabelValue(dm, rest, f, 1));
    PetscCall(DMSetLabelValue(dm, to_string(EdgeKind::Source), f, 1));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

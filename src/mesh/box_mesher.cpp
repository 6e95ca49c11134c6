#include "vibrotherm/mesh/box_mesher.hpp"

#include <cmath>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {
namespace {

/// The side of a boundary face from its index-space centroid (0..3 as Side, 4 front, 5 back).
int FaceSide(const PetscReal* c, const BoxGrid& grid) {
  const auto at = [](double v, double target) { return std::abs(v - target) < 1e-9; };
  if (at(c[1], 0)) return static_cast<int>(Side::Bottom);
  if (at(c[0], grid.cells(0))) return static_cast<int>(Side::Right);
  if (at(c[1], grid.cells(1))) return static_cast<int>(Side::Top);
  if (at(c[0], 0)) return static_cast<int>(Side::Left);
  return at(c[2], grid.cells(2)) ? 4 : 5;
}

/// Labels the outer faces (kind, side) and the cracks' faces (crack = its number from 1, crack_face ids in point order).
PetscErrorCode LabelFaces(DM dm, const SpecimenGeometry& g, const BoxGrid& grid, PetscInt* crack_faces) {
  PetscFunctionBeginUser;
  for (const char* name : {labels::crack, labels::crack_face, labels::crack_tip, labels::side, labels::sink})
    PetscCall(DMCreateLabel(dm, name));
  for (EdgeKind kind : all_edge_kinds()) PetscCall(DMCreateLabel(dm, to_string(kind)));
  DMLabel crack, ids, side;
  PetscCall(DMGetLabel(dm, labels::crack, &crack));
  PetscCall(DMGetLabel(dm, labels::crack_face, &ids));
  PetscCall(DMGetLabel(dm, labels::side, &side));
  PetscInt fStart, fEnd;
  PetscCall(FacetRange(dm, &fStart, &fEnd));
  *crack_faces = 0;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt cells;
    PetscReal area, c[3], n[3];
    PetscCall(DMPlexGetSupportSize(dm, f, &cells));
    PetscCall(DMPlexComputeCellGeometryFVM(dm, f, &area, c, n));
    const int on = cells == 2 ? grid.crack_at({c[0], c[1], c[2]}) : -1;
    if (on >= 0) {
      PetscCall(DMLabelSetValue(crack, f, on + 1));
      PetscCall(DMLabelSetValue(ids, f, (*crack_faces)++));
    } else if (cells == 1) {
      const int s = FaceSide(c, grid);
      const EdgeKind kind = s < 4 ? g.edges[s] : g.depth_edges[s - 4];
      PetscCall(DMLabelSetValue(side, f, s));
      PetscCall(DMSetLabelValue(dm, to_string(kind), f, 1));
      PetscCall(DMSetLabelValue(dm, labels::sink, f, 1));  // as in 2D: every outer face a heat sink by default
    }
  }
  PetscFunctionReturn(0);
}


}  // namespace

PetscErrorCode CreateBoxPlex(MPI_Comm comm, const SpecimenGeometry& g, const BoxGrid& grid, DM* dm,
                             PetscInt* crack_faces) {
  PetscFunctionBeginUser;
  const PetscInt faces[3] = {grid.cells(0), grid.cells(1), grid.cells(2)};
  const PetscReal lower[3] = {0, 0, 0}, upper[3] = {PetscReal(faces[0]), PetscReal(faces[1]), PetscReal(faces[2])};
  // PETSc 3.18 builds every cell on rank 0 (the serial mesh the crack split needs).
  PetscCall(DMPlexCreateBoxMesh(comm, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, dm));
  for (const char* name : {"marker", "Face Sets"}) PetscCall(DMRemoveLabel(*dm, name, nullptr));
  PetscCall(PetscObjectSetName((PetscObject)*dm, "specimen"));
  PetscCall(LabelFaces(*dm, g, grid, crack_faces));
  PetscCall(MoveVertices(*dm, [&](PetscScalar* x, PetscInt n) {  // index-space coordinates → the graded, sheared grid
    for (PetscInt v = 0; v < n / 3; ++v) {
      const std::array<double, 3> p = grid.position({x[3 * v], x[3 * v + 1], x[3 * v + 2]});
      for (int d = 0; d < 3; ++d) x[3 * v + d] = p[d];
    }
  }));
  PetscCall(LabelBoxPatch(*dm, g));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh

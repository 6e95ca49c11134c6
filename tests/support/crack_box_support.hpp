// A 3D box with a planar crack labelled on its faces, for the 3D crack tests (split, grids).
#pragma once

#include <petscdmplex.h>

#include <cmath>

#include "box_mesh_support.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::testing {

struct CrackBox {
  DM dm = nullptr;
  PetscInt crack_faces = 0;
  ~CrackBox() { (void)DMDestroy(&dm); }
};

/// [-1,1]³ in 8³ hexes (or Kuhn tets) with the crack x0 ≤ x ≤ x1, |y| ≤ 0.5 in the plane z = 0.
inline PetscErrorCode MakeCrackBox(bool simplex, double x0, double x1, CrackBox* box) {
  PetscFunctionBeginUser;
  const PetscInt faces[3] = {8, 8, 8};
  const PetscReal lower[3] = {-1, -1, -1}, upper[3] = {1, 1, 1};
  if (simplex) PetscCall(KuhnSimplices(3, faces, lower, upper, &box->dm));
  else PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_SELF, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, &box->dm));
  PetscCall(DMCreateLabel(box->dm, mesh::labels::crack));
  PetscCall(DMCreateLabel(box->dm, mesh::labels::crack_tip));
  DMLabel crack;
  PetscCall(DMGetLabel(box->dm, mesh::labels::crack, &crack));
  PetscInt fStart, fEnd;
  PetscCall(mesh::FacetRange(box->dm, &fStart, &fEnd));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscReal area, c[3], n[3];
    PetscCall(DMPlexComputeCellGeometryFVM(box->dm, f, &area, c, n));
    if (std::abs(c[2]) < 1e-12 && c[0] > x0 && c[0] < x1 && std::abs(c[1]) < 0.5) {
      PetscCall(DMLabelSetValue(crack, f, 1));
      ++box->crack_faces;
    }
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::testing

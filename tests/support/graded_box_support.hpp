// Hexahedral boxes graded along each axis (DMPlexCreateBoxMesh, its vertices
// moved onto given node lines: every cell stays a rectangular box), with
// chosen outer faces labelled `sink`, distributed over a communicator: the 3D
// heat meshes of the surface-source tests, fine where the source heats and
// coarse out to faces far enough not to matter.
#pragma once

#include <petscdmplex.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "box_mesh_support.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"

namespace vibrotherm::testing {

/// n + 1 nodes from 0 to `length`: a C¹ map of s = i/n, uniform (spacing fine/(s_fine n)) on [0, fine]
/// (s ≤ s_fine), growing exponentially from there to `length`. Needs length > fine/s_fine.
inline std::vector<double> GradedAxis(double fine, double length, double s_fine, int n) {
  const double slope = fine / s_fine;
  const auto end = [&](double beta) { return fine + slope * std::expm1(beta * (1.0 - s_fine)) / beta; };
  double lo = 1e-12, hi = 100.0;  // end(β) grows with β: bisection
  for (int it = 0; it < 200; ++it) (end(0.5 * (lo + hi)) < length ? lo : hi) = 0.5 * (lo + hi);
  const double beta = 0.5 * (lo + hi);
  std::vector<double> nodes(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    nodes[i] = s <= s_fine ? slope * s : fine + slope * std::expm1(beta * (s - s_fine)) / beta;
  }
  nodes[n] = length;
  return nodes;
}

/// The nodes of `half` (from 0 outwards) mirrored about 0: the finest cells on both sides of 0.
inline std::vector<double> MirroredAxis(const std::vector<double>& half) {
  std::vector<double> nodes;
  for (std::size_t i = half.size(); i-- > 1;) nodes.push_back(-half[i]);
  nodes.insert(nodes.end(), half.begin(), half.end());
  return nodes;
}

/// Labels `sink` (value 1) the outer faces of a 3D mesh whose centre c satisfies sink(c).
inline PetscErrorCode LabelSinkFaces(DM dm, const std::function<bool(const double*)>& sink) {
  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, mesh::labels::sink));
  PetscInt fStart, fEnd, vStart, vEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  Vec coordinates;
  const PetscScalar* x;
  PetscCall(DMGetCoordinatesLocal(dm, &coordinates));
  PetscCall(VecGetArrayRead(coordinates, &x));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt support, closure_size, *closure = nullptr, corners = 0;
    PetscCall(DMPlexGetSupportSize(dm, f, &support));
    if (support != 1) continue;
    double centre[3] = {0, 0, 0};
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &closure_size, &closure));
    for (PetscInt k = 0; k < 2 * closure_size; k += 2)
      if (closure[k] >= vStart && closure[k] < vEnd) {
        for (int d = 0; d < 3; ++d) centre[d] += PetscRealPart(x[3 * (closure[k] - vStart) + d]);
        ++corners;
      }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &closure_size, &closure));
    for (double& c : centre) c /= corners;
    if (sink(centre)) PetscCall(DMSetLabelValue(dm, mesh::labels::sink, f, 1));
  }
  PetscCall(VecRestoreArrayRead(coordinates, &x));
  PetscFunctionReturn(0);
}

/// The hexahedra (simplex: each split into 6 tetrahedra, KuhnSimplices) between the node lines
/// nodes[0..2], outer faces whose centre c satisfies sink(c) labelled `sink` (value 1),
/// distributed over comm (one rank: as built).
inline PetscErrorCode GradedBox(MPI_Comm comm, const std::array<std::vector<double>, 3>& nodes, bool simplex,
                                const std::function<bool(const double*)>& sink, DM* dm) {
  PetscFunctionBeginUser;
  const PetscInt faces[3] = {static_cast<PetscInt>(nodes[0].size()) - 1, static_cast<PetscInt>(nodes[1].size()) - 1,
                             static_cast<PetscInt>(nodes[2].size()) - 1};
  const PetscReal lower[3] = {0, 0, 0}, upper[3] = {1, 1, 1};
  if (simplex) PetscCall(KuhnSimplices(3, faces, lower, upper, dm, comm));
  else PetscCall(DMPlexCreateBoxMesh(comm, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, dm));
  PetscCall(MoveVertices(*dm, [&](PetscScalar* x, PetscInt n) {  // built on one rank: every vertex here
    for (PetscInt i = 0; i < n; ++i) x[i] = nodes[i % 3][std::lround(PetscRealPart(x[i]) * faces[i % 3])];
  }));
  PetscCall(LabelSinkFaces(*dm, sink));
  DM distributed = nullptr;
  PetscCall(DMPlexDistribute(*dm, 0, nullptr, &distributed));
  if (distributed) {
    PetscCall(DMDestroy(dm));
    *dm = distributed;
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::testing

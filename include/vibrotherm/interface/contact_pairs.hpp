// The node pairs across the cracks of a split mesh, by one walk of the cohesive cells'
// closures in both dimensions: a cohesive cell's cone is its two faces then its tensor
// points (2D: two tensor edges; 3D: tensor faces, whose cones end in tensor edges), and
// each tensor point's cone starts with the pair it joins. So a pair is keyed by the point
// joining it: the cohesive cell for the faces' middle nodes, a tensor face for the edges'
// (3D), a tensor edge for the vertices. Pairs whose points carry no dofs (the faces and
// edges with degree 1), the crack front (not split: its pair is one point) and pairs
// joined by another rank's point are skipped.
#pragma once

#include <petscdmplex.h>

#include <array>
#include <functional>

namespace vibrotherm::interface {

struct ContactPair {
  PetscInt key;                  ///< the point joining the pair
  std::array<PetscInt, 2> side;  ///< side[plus] is on the + face, side[1 − plus] on the −
  bool vertex;                   ///< a vertex pair (else the middle node of a face or an edge)
};

/// visit(cohesive cell, plus, pair) for this rank's cohesive cells in point order, each
/// cell's pairs from its own (the faces) down to its vertices. A pair shared by several
/// cohesive cells is visited once for each. plus: mesh::PlusSide of the cell.
using ContactPairVisitor = std::function<PetscErrorCode(PetscInt, int, const ContactPair&)>;
PetscErrorCode ForEachContactPair(DM dm, int degree, const ContactPairVisitor& visit);

}  // namespace vibrotherm::interface

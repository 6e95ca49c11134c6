#include "vibrotherm/interface/contact_pairs.hpp"

#include <vector>

#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::interface {
namespace {

struct Walk {
  DM dm;
  int degree;
  std::vector<bool> ghost;
  PetscInt chart0, vertex_start, vertex_end;
  const ContactPairVisitor* visit;

  /// The pair joined by `joint` (a cohesive cell or one of its tensor points), then its tensor points'.
  PetscErrorCode Pairs(PetscInt cohesive, int plus, PetscInt joint) const {
    PetscFunctionBeginUser;
    const PetscInt* cone;
    PetscInt size;
    PetscCall(DMPlexGetConeSize(dm, joint, &size));
    PetscCall(DMPlexGetCone(dm, joint, &cone));
    const bool vertex = cone[0] >= vertex_start && cone[0] < vertex_end;  // vertices carry dofs, the rest with Q2
    if (cone[0] != cone[1] && !ghost[joint - chart0] && (vertex || degree == 2))
      PetscCall((*visit)(cohesive, plus, ContactPair{joint, {cone[0], cone[1]}, vertex}));
    for (PetscInt k = 2; k < size; ++k) PetscCall(Pairs(cohesive, plus, cone[k]));
    PetscFunctionReturn(0);
  }
};

}  // namespace

PetscErrorCode ForEachContactPair(DM dm, int degree, const ContactPairVisitor& visit) {
  PetscFunctionBeginUser;
  Walk walk{dm, degree, {}, 0, 0, 0, &visit};
  PetscCall(mesh::GhostPoints(dm, &walk.ghost));
  PetscCall(DMPlexGetChart(dm, &walk.chart0, nullptr));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &walk.vertex_start, &walk.vertex_end));
  std::vector<PetscInt> cohesive;
  PetscCall(mesh::CohesiveCells(dm, &cohesive));
  for (PetscInt c : cohesive) {
    int plus;
    PetscCall(mesh::PlusSide(dm, c, &plus));
    PetscCall(walk.Pairs(c, plus, c));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface

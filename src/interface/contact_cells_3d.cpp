#include "vibrotherm/interface/contact_cells_3d.hpp"

#include <petscdmplex.h>

#include <cmath>
#include <map>

#include "vibrotherm/geometry/frame.hpp"
#include "vibrotherm/interface/contact_pairs.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::interface {
namespace {

using geometry::Vec3;

/// The frame of a crack face's normal, oriented by the 2D rule (header).
void FrameOf(const PetscReal* normal, ContactCell* cell) {
  const geometry::Frame<3> f = geometry::CrackFrame({normal[0], normal[1], normal[2]});
  for (int d = 0; d < 3; ++d) cell->n[d] = f.normal[d], cell->s[d] = f.tangent[0][d], cell->s2[d] = f.tangent[1][d];
}

/// ∫φ dA of every node of the crack's faces, summed over all ranks, at the node's
/// first dof of a local vector (both faces of a cohesive cell carry it).
PetscErrorCode NodeWeights(const fe::LagrangeSpace& space, const std::vector<PetscInt>& cohesive, Vec* local) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  Vec global;
  PetscCall(DMCreateLocalVector(dm, local));
  PetscCall(DMCreateGlobalVector(dm, &global));
  PetscCall(VecSet(*local, 0.0));
  PetscCall(VecSet(global, 0.0));
  std::vector<PetscInt> offsets;
  std::vector<double> weights;
  for (PetscInt c : cohesive) {
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    for (int side = 0; side < 2; ++side) {
      double area;
      offsets.clear(), weights.clear();
      PetscCall(space.FaceNodes(cone[side], &offsets, &weights, &area));
      PetscCall(
          VecSetValues(*local, static_cast<PetscInt>(offsets.size()), offsets.data(), weights.data(), ADD_VALUES));
    }
  }
  PetscCall(VecAssemblyBegin(*local));
  PetscCall(VecAssemblyEnd(*local));
  PetscCall(DMLocalToGlobal(dm, *local, ADD_VALUES, global));
  PetscCall(DMGlobalToLocal(dm, global, INSERT_VALUES, *local));
  PetscCall(VecDestroy(&global));
  PetscFunctionReturn(0);
}

/// The frame and crack of a cohesive cell (from its first face, cone[0]), for its contact cells.
PetscErrorCode CellFrame(DM dm, DMLabel crack_label, PetscInt c, ContactCell* frame) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  PetscCall(DMPlexGetCone(dm, c, &cone));
  PetscReal area, centre[3], normal[3];
  PetscCall(DMPlexComputeCellGeometryFVM(dm, cone[0], &area, centre, normal));
  *frame = ContactCell{};
  FrameOf(normal, frame);
  PetscInt crack;  // the crack's number from 1 (box_mesher.cpp)
  PetscCall(DMLabelGetValue(crack_label, cone[0], &crack));
  PetscCheck(crack >= 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "3D crack: a cohesive cell's face is not labelled %s",
             mesh::labels::crack);
  frame->crack = crack - 1;
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ContactCells3D(const fe::LagrangeSpace& space, std::vector<ContactCell>* cells) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  std::vector<PetscInt> cohesive;
  PetscCall(mesh::CohesiveCells(dm, &cohesive));
  Vec weights;
  PetscCall(NodeWeights(space, cohesive, &weights));
  mesh::VertexPositions<3> x;
  PetscCall(x.Setup(dm));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  const PetscScalar* w;
  PetscCall(VecGetArrayRead(weights, &w));
  DMLabel crack_label;
  PetscCall(DMGetLabel(dm, mesh::labels::crack, &crack_label));
  std::map<PetscInt, ContactCell> by_point;
  PetscInt framed = -1;  // the cohesive cell whose frame `frame` holds
  ContactCell frame{};
  const auto add = [&](PetscInt c, int plus, const ContactPair& pair) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (c != framed) {
      PetscCall(CellFrame(dm, crack_label, c, &frame));
      framed = c;
    }
    ContactCell cell = frame;
    cell.plus = pair.side[plus], cell.minus = pair.side[1 - plus];
    PetscInt off;
    PetscCall(PetscSectionGetOffset(section, cell.minus, &off));
    cell.weight = PetscRealPart(w[off]);
    Vec3 p;
    PetscCall(mesh::CellCentroid(dm, x, cell.minus, &p));
    cell.x = p[0], cell.y = p[1], cell.z = p[2];
    by_point[pair.key] = cell;
    PetscFunctionReturn(0);
  };
  PetscCall(ForEachContactPair(dm, static_cast<int>(space.degree()), add));
  PetscCall(VecRestoreArrayRead(weights, &w));
  PetscCall(VecDestroy(&weights));
  cells->clear();
  for (const auto& [point, cell] : by_point) cells->push_back(cell);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface

#include "vibrotherm/interface/contact_cells_3d.hpp"

#include <petscdmplex.h>

#include <cmath>
#include <map>

#include "vibrotherm/geometry/frame.hpp"
#include "vibrotherm/mesh/plex/crack_split.hpp"
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

/// This rank's cohesive cells.
PetscErrorCode CohesiveCells(DM dm, std::vector<PetscInt>* cells) {
  PetscFunctionBeginUser;
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(mesh::IsCohesiveCell(dm, c, &cohesive));
    if (cohesive) cells->push_back(c);
  }
  PetscFunctionReturn(0);
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

/// The pairs of one cohesive cell, keyed by the point joining them (the cell for
/// the faces, a tensor face for edges, a tensor edge for vertices).
PetscErrorCode CellPairs(DM dm, PetscInt c, int degree, const std::vector<bool>& ghost, PetscInt chart0,
                         std::map<PetscInt, std::array<PetscInt, 2>>* pairs) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  PetscInt size;
  PetscCall(DMPlexGetConeSize(dm, c, &size));
  PetscCall(DMPlexGetCone(dm, c, &cone));
  if (degree == 2) (*pairs)[c] = {cone[0], cone[1]};
  for (PetscInt k = 2; k < size; ++k) {  // tensor faces: (edge 0, edge 1, tensor edge, tensor edge)
    const PetscInt* edges;
    PetscCall(DMPlexGetCone(dm, cone[k], &edges));
    if (degree == 2 && edges[0] != edges[1] && !ghost[cone[k] - chart0]) (*pairs)[cone[k]] = {edges[0], edges[1]};
    for (int j = 2; j < 4; ++j) {
      const PetscInt* ends;
      PetscCall(DMPlexGetCone(dm, edges[j], &ends));
      if (ends[0] != ends[1] && !ghost[edges[j] - chart0]) (*pairs)[edges[j]] = {ends[0], ends[1]};
    }
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ContactCells3D(const fe::LagrangeSpace& space, std::vector<ContactCell>* cells) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  std::vector<PetscInt> cohesive;
  PetscCall(CohesiveCells(dm, &cohesive));
  Vec weights;
  PetscCall(NodeWeights(space, cohesive, &weights));
  mesh::VertexPositions<3> x;
  PetscCall(x.Setup(dm));
  std::vector<bool> ghost;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  const PetscScalar* w;
  PetscCall(VecGetArrayRead(weights, &w));
  DMLabel crack_label;
  PetscCall(DMGetLabel(dm, mesh::labels::crack, &crack_label));
  std::map<PetscInt, ContactCell> by_point;
  for (PetscInt c : cohesive) {
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    PetscReal area, centre[3], normal[3];
    PetscCall(DMPlexComputeCellGeometryFVM(dm, cone[0], &area, centre, normal));
    ContactCell frame{};
    FrameOf(normal, &frame);
    PetscInt crack;  // the crack's number from 1 (box_mesher.cpp)
    PetscCall(DMLabelGetValue(crack_label, cone[0], &crack));
    PetscCheck(crack >= 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "3D crack: a cohesive cell's face is not labelled %s",
               mesh::labels::crack);
    frame.crack = crack - 1;
    int plus;  // the split labelled the + face on the serial mesh
    PetscCall(mesh::PlusSide(dm, c, &plus));
    std::map<PetscInt, std::array<PetscInt, 2>> pairs;
    PetscCall(CellPairs(dm, c, static_cast<int>(space.degree()), ghost, chart0, &pairs));
    for (const auto& [key, pair] : pairs) {
      ContactCell cell = frame;
      cell.plus = pair[plus], cell.minus = pair[1 - plus];
      PetscInt off;
      PetscCall(PetscSectionGetOffset(section, cell.minus, &off));
      cell.weight = PetscRealPart(w[off]);
      Vec3 p;
      PetscCall(mesh::CellCentroid(dm, x, cell.minus, &p));
      cell.x = p[0], cell.y = p[1], cell.z = p[2];
      by_point[key] = cell;
    }
  }
  PetscCall(VecRestoreArrayRead(weights, &w));
  PetscCall(VecDestroy(&weights));
  cells->clear();
  for (const auto& [point, cell] : by_point) cells->push_back(cell);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface

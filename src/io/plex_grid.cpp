#include "vibrotherm/io/plex_grid.hpp"

#include <petscdmplex.h>

#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::io {
namespace {

/// The global number of every local vertex v, at (*numbers)[v − vStart]
/// (DMPlexGetVertexNumbering encodes those owned elsewhere as −(g + 1)).
PetscErrorCode GlobalVertexNumbers(DM dm, PetscInt* vStart, std::vector<PetscInt>* numbers) {
  PetscFunctionBeginUser;
  IS numbering;
  const PetscInt* number;
  PetscInt vEnd;
  PetscCall(DMPlexGetVertexNumbering(dm, &numbering));
  PetscCall(DMPlexGetDepthStratum(dm, 0, vStart, &vEnd));
  PetscCall(ISGetIndices(numbering, &number));
  numbers->resize(vEnd - *vStart);
  for (PetscInt i = 0; i < vEnd - *vStart; ++i) (*numbers)[i] = number[i] >= 0 ? number[i] : -(number[i] + 1);
  PetscCall(ISRestoreIndices(numbering, &number));
  PetscFunctionReturn(0);
}

/// The owned cells of one kind: bulk or cohesive.
PetscErrorCode OwnedCells(DM dm, bool cohesive, std::vector<PetscInt>* cells) {
  PetscFunctionBeginUser;
  std::vector<bool> ghost;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0, cStart, cEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  cells->clear();
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool is_cohesive;
    PetscCall(mesh::IsCohesiveCell(dm, c, &is_cohesive));
    if (!ghost[c - chart0] && is_cohesive == cohesive) cells->push_back(c);
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode OwnedVertices(DM dm, PlexVertices* out) {
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetVertexNumbering(dm, &out->numbering));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  const PetscInt* number;
  PetscCall(ISGetIndices(out->numbering, &number));
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm));
  out->rows.clear();
  out->xy.clear();
  for (PetscInt v = vStart; v < vEnd; ++v) {
    if (number[v - vStart] < 0) continue;  // owned by another rank
    out->rows.push_back(number[v - vStart]);
    const auto p = x(v);
    out->xy.insert(out->xy.end(), {p[0], p[1]});
  }
  PetscCall(ISRestoreIndices(out->numbering, &number));
  const PetscInt owned = static_cast<PetscInt>(out->rows.size());
  PetscCallMPI(MPI_Allreduce(&owned, &out->global, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode OwnedBulkCells(DM dm, std::vector<PetscInt>* cells, PetscInt* corners) {
  PetscFunctionBeginUser;
  PetscInt vStart, k = 0;
  std::vector<PetscInt> number, owned;
  PetscCall(GlobalVertexNumbers(dm, &vStart, &number));
  PetscCall(OwnedCells(dm, false, &owned));
  cells->clear();
  for (PetscInt c : owned) {
    PetscInt n, *closure = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
    k = 0;
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt p = closure[2 * i] - vStart;
      if (p < 0 || p >= static_cast<PetscInt>(number.size())) continue;  // not a vertex
      cells->push_back(number[p]);
      ++k;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
  }
  // A rank without cells has seen no corners: take the others' count.
  PetscCallMPI(MPI_Allreduce(&k, corners, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode OwnedCohesiveSegments(DM dm, std::vector<PetscInt>* segments) {
  PetscFunctionBeginUser;
  PetscInt vStart;
  std::vector<PetscInt> number, owned;
  PetscCall(GlobalVertexNumbers(dm, &vStart, &number));
  PetscCall(OwnedCells(dm, true, &owned));
  segments->clear();
  for (PetscInt c : owned) {
    const PetscInt *faces, *ends;
    PetscCall(DMPlexGetCone(dm, c, &faces));  // cone: − face, + face, tensor edges
    PetscCall(DMPlexGetCone(dm, faces[0], &ends));
    for (int e = 0; e < 2; ++e) segments->push_back(number[ends[e] - vStart]);
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

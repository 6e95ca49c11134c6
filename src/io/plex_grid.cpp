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

/// The owned vertices' global numbers and D coordinates (number: DMPlexGetVertexNumbering's).
template <std::size_t D>
PetscErrorCode AppendOwned(DM dm, const PetscInt* number, PetscInt vStart, PetscInt vEnd, PlexVertices* out) {
  PetscFunctionBeginUser;
  mesh::VertexPositions<D> x;
  PetscCall(x.Setup(dm));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    if (number[v - vStart] < 0) continue;  // owned by another rank
    out->rows.push_back(number[v - vStart]);
    const auto p = x(v);
    out->coordinates.insert(out->coordinates.end(), p.begin(), p.end());
  }
  PetscFunctionReturn(0);
}

}  // namespace

const char* XdmfTopologyType(int cell_dim, PetscInt corners) {
  if (corners == 2) return "Polyline";
  if (cell_dim == 3 && corners == 4) return "Tetrahedron";
  if (cell_dim == 3 && corners == 8) return "Hexahedron";
  return corners == 3 ? "Triangle" : "Quadrilateral";
}

PetscErrorCode OwnedVertices(DM dm, PlexVertices* out) {
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetVertexNumbering(dm, &out->numbering));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  const PetscInt* number;
  PetscCall(ISGetIndices(out->numbering, &number));
  PetscInt dim;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  out->dim = static_cast<int>(dim);
  out->rows.clear();
  out->coordinates.clear();
  if (dim == 3) PetscCall(AppendOwned<3>(dm, number, vStart, vEnd, out));
  else PetscCall(AppendOwned<2>(dm, number, vStart, vEnd, out));
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
  PetscInt dim;
  PetscCall(DMGetDimension(dm, &dim));
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
    if (dim == 3) {  // Plex's first face points inward: VTK's order is the inverted one
      DMPolytopeType type;
      PetscCall(DMPlexGetCellType(dm, c, &type));
      PetscCall(DMPlexInvertCell(type, cells->data() + cells->size() - k));
    }
  }
  // A rank without cells has seen no corners: take the others' count.
  PetscCallMPI(MPI_Allreduce(&k, corners, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode OwnedCohesiveFaces(DM dm, std::vector<PetscInt>* faces, PetscInt* corners) {
  PetscFunctionBeginUser;
  PetscInt vStart, dim, k = 0;
  std::vector<PetscInt> number, owned, face_corners, edges;
  PetscCall(GlobalVertexNumbers(dm, &vStart, &number));
  PetscCall(OwnedCells(dm, true, &owned));
  PetscCall(DMGetDimension(dm, &dim));
  faces->clear();
  for (PetscInt c : owned) {
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));  // cone: − face, + face, tensor edges or faces
    if (dim == 2) {
      const PetscInt* ends;
      PetscCall(DMPlexGetCone(dm, cone[0], &ends));
      face_corners.assign(ends, ends + 2);
    } else {
      PetscCall(mesh::FaceCycle(dm, cone[0], &face_corners, &edges));
    }
    k = static_cast<PetscInt>(face_corners.size());
    for (PetscInt v : face_corners) faces->push_back(number[v - vStart]);
  }
  PetscCallMPI(MPI_Allreduce(&k, corners, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io

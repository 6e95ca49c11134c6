// A DMPlex as the flat arrays an HDF5/XDMF grid needs: this rank's owned
// vertices with their global numbers and coordinates, its owned bulk cells and
// its owned cohesive (crack) cells, all by global vertex number.
#pragma once

#include <petscdm.h>

#include <vector>

namespace vibrotherm::io {

struct PlexVertices {
  IS numbering = nullptr;     ///< DMPlexGetVertexNumbering (owned by the DM)
  std::vector<PetscInt> rows;  ///< global number of each owned vertex
  std::vector<double> xy;      ///< their coordinates, 2 per vertex
  PetscInt global = 0;         ///< vertices on all ranks
};
PetscErrorCode OwnedVertices(DM dm, PlexVertices* vertices);

/// Owned bulk cells, corners in closure order (cyclic for triangles and quads);
/// *corners: the corners per cell (the same on every rank).
PetscErrorCode OwnedBulkCells(DM dm, std::vector<PetscInt>* cells, PetscInt* corners);

/// Owned cohesive cells as line segments: the two vertices of each one's − face.
/// (The ± faces coincide, so the segment is the crack element itself.)
PetscErrorCode OwnedCohesiveSegments(DM dm, std::vector<PetscInt>* segments);

}  // namespace vibrotherm::io

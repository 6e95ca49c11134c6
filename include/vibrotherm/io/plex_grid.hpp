// A DMPlex as the flat arrays an HDF5/XDMF grid needs: this rank's owned
// vertices with their global numbers and coordinates, its owned bulk cells and
// its owned cohesive (crack) cells, all by global vertex number, in 2D and 3D.
// Corners are in XDMF's (VTK's) order: cyclic for triangles and quads as DMPlex
// has them; 3D cells through DMPlexInvertCell (Plex stores the first face of a
// hexahedron or tetrahedron with its normal inward, VTK outward).
#pragma once

#include <petscdm.h>

#include <vector>

namespace vibrotherm::io {

struct PlexVertices {
  IS numbering = nullptr;     ///< DMPlexGetVertexNumbering (owned by the DM)
  std::vector<PetscInt> rows;  ///< global number of each owned vertex
  int dim = 2;                 ///< coordinates per vertex (the DM's coordinate dimension)
  std::vector<double> coordinates;  ///< dim per vertex
  PetscInt global = 0;         ///< vertices on all ranks
};
PetscErrorCode OwnedVertices(DM dm, PlexVertices* vertices);

/// Owned bulk cells, corners in XDMF order; *corners: the corners per cell (the same on every rank).
PetscErrorCode OwnedBulkCells(DM dm, std::vector<PetscInt>* cells, PetscInt* corners);

/// Owned cohesive cells as the vertices of each one's − face: segments in 2D, triangles or
/// quadrilaterals in 3D (the ± faces coincide, so the face is the crack element itself).
PetscErrorCode OwnedCohesiveFaces(DM dm, std::vector<PetscInt>* faces, PetscInt* corners);

/// XDMF's TopologyType of cells of dimension `cell_dim` (1: lines, 2: polygons, 3: solids) with
/// `corners` corners ("Polyline": 2-node lines).
const char* XdmfTopologyType(int cell_dim, PetscInt corners);

}  // namespace vibrotherm::io

// XDMF text indexing grids and fields stored in an HDF5 file, in the shapes
// ParaView 5.11 reads well: a temporal collection of one grid per .xmf file
// (every XDMF reader gives one dataset with a time axis), or a spatial
// collection of named static grids (Xdmf3 Reader T and XDMF Reader give one
// named block per grid).
#pragma once

#include <petscsys.h>

#include <ostream>
#include <string>
#include <vector>

namespace vibrotherm::io {

struct XdmfGrid {
  std::string name;
  std::string topology_type;  ///< plex_grid.hpp's XdmfTopologyType: "Triangle", "Hexahedron", "Polyline" (2-node lines)...
  PetscInt cells = 0, corners = 0, vertices = 0;
  int dim = 2;                     ///< coordinates per vertex (XY or XYZ)
  std::string topology, geometry;  ///< "<file>.h5:/<path>" of cells × corners and vertices × dim
};

struct XdmfAttribute {
  std::string name;
  int components = 1;  ///< 1 (Scalar) or 3 (Vector)
  bool cell = false;   ///< cell-centred (else node-centred)
  std::string data;    ///< "<file>.h5:/<path>"
};

/// One output of a series: its time (or frequency) and the attributes written then.
struct XdmfStep {
  double time = 0.0;
  std::vector<XdmfAttribute> attributes;
};

/// A whole .xmf: the grid's outputs as a temporal collection.
void WriteXdmfSeries(std::ostream& out, const XdmfGrid& grid, const std::vector<XdmfStep>& steps);
/// A whole .xmf: the grids (no fields) as a spatial collection named `name`.
void WriteXdmfCollection(std::ostream& out, const std::string& name, const std::vector<XdmfGrid>& grids);

}  // namespace vibrotherm::io

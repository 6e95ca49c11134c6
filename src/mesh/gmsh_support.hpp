// Helpers shared by the gmsh-based mesh generators (private to src/mesh).
// gmsh's API is a process-wide singleton: one GmshSession per generated mesh.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh::gmsh_support {

using DimTags = std::vector<std::pair<int, int>>;

/// RAII for the gmsh session (single-threaded, silent).
struct GmshSession {
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// Opens a mesh file or geometry script in the session; a file that is missing or that gmsh
/// cannot read is refused with `where` (the option and the file) and gmsh's own message.
void OpenFile(const std::string& path, const std::string& where);

/// gmsh node tags → dense 0-based vertex indices, with coordinates.
struct NodeMap {
  std::map<std::size_t, int> index;
  std::vector<double> coords;
  int operator()(std::size_t tag) const { return index.at(tag); }
};
NodeMap collect_nodes();

/// 2D cells of the whole model into mesh (corners and cells); rejects mixed or higher-order meshes.
void collect_cells(const NodeMap& nodes, MeshData& mesh, const std::string& where);

/// Reverses the clockwise cells of mesh (keeps the first vertex).
void orient_counter_clockwise(MeshData& mesh);

/// Mesh edges (2-node lines) of a model curve, tagged `tag`.
std::vector<MeshEdge> curve_edges(const NodeMap& nodes, int curve, int tag);

void append(std::vector<MeshEdge>& to, const std::vector<MeshEdge>& from);

/// Whether the current 2D mesh contains triangles.
bool has_triangles();

/// Outer curves of a generated rectangle specimen: side edges, mechanical kinds and
/// sinks (every outer edge is a sink by default) into mesh.
void collect_rectangle_edges(const NodeMap& nodes, const SpecimenGeometry& g, MeshData& mesh);

/// The current 2D mesh of a generated rectangle: cells, outer edges, and crack i's
/// edges from its model curves crack_curves[i] (named crack1, crack2, ...).
MeshData collect_rectangle_mesh(const SpecimenGeometry& g, const std::vector<std::vector<int>>& crack_curves,
                                const std::string& where);

/// The mesh size as a background field: size_min within dist_min of `curves`,
/// growing linearly to size_max at dist_max; size_max everywhere without curves.
struct GradedSize {
  double size_min, size_max, dist_min, dist_max;
  int points_per_curve;
};
void set_graded_size(const std::vector<double>& curves, const GradedSize& size);

/// End points of a model curve (start, end).
std::pair<std::array<double, 2>, std::array<double, 2>> curve_end_points(int curve);

}  // namespace vibrotherm::mesh::gmsh_support

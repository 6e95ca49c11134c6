// A serial 2D mesh as plain arrays, the bridge between gmsh and DMPlex.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

struct MeshEdge {
  int v0, v1;  ///< vertex indices
  int tag;     ///< meaning depends on the list it is in
};

struct MeshData {
  int corners = 4;              ///< 3: triangles, 4: quadrilaterals
  std::vector<double> coords;   ///< x, y per vertex
  std::vector<int> cells;       ///< `corners` vertex indices per cell
  /// Outer edges per mechanical kind (tag = EdgeKind) and per thermal sink (tag 1).
  std::vector<MeshEdge> kind_edges, sink_edges;
  /// Outer edges with their side of the rectangle (tag = Side; -1 for mesh files).
  std::vector<MeshEdge> side_edges;
  /// Crack edges, tag = crack index (0-based).
  std::vector<MeshEdge> crack_edges;
  std::vector<std::string> crack_names;
  /// What the generator could not do as asked (a crack without its mirror-symmetric layers, and why).
  std::vector<std::string> notes;

  int vertex_count() const { return static_cast<int>(coords.size() / 2); }
  int cell_count() const { return static_cast<int>(cells.size() / corners); }
};

/// Meshes the specimen with gmsh (OpenCASCADE kernel; quads by blossom
/// recombination of a frontal-Delaunay mesh). Throws std::runtime_error on failure.
MeshData generate_specimen_mesh(const SpecimenGeometry& geometry);

/// Reads a gmsh .msh file with physical curve groups named source, absorbing,
/// free, roller, fixed, sink and crack*. Throws std::invalid_argument naming -mesh_file.
MeshData read_mesh_file(const std::string& path);

}  // namespace vibrotherm::mesh

namespace vibrotherm::mesh {
/// Whether a mesh file's specimen is the rectangle [0, W] × [0, H] with straight
/// cracks; fills geometry (sizes: longest outer edge, mean crack edge) if so,
/// else says why not in *why ("crack_b bends at (x, y)").
bool rectangle_geometry(const MeshData& mesh, SpecimenGeometry* geometry, std::string* why);
/// Keeps the outer edges of a generated heat mesh that lie on a sink edge of `file`.
void keep_sinks_of(const MeshData& file, MeshData* heat);

/// Every crack must be one open, unbranched line of edges; throws
/// std::invalid_argument naming the crack otherwise.
void check_crack_lines(const MeshData& mesh, const std::string& where);
/// No two cracks may meet (a shared node, or edges that cross): throws
/// std::invalid_argument naming both cracks and where they meet.
void check_cracks_apart(const MeshData& mesh, const std::string& where);
}  // namespace vibrotherm::mesh

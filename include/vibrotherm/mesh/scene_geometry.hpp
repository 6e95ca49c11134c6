// The specimen as the user describes it: a rectangle [0, W] × [0, H] (origin at
// the bottom-left corner, y up) with straight cracks, mesh sizes and the kind
// of each outer edge; with a depth D > 0 the box [0, W] × [0, H] × [0, D] (z
// toward the viewer) with one buried rectangular crack (box_grid.hpp). Plain
// data with validation that names the option.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace vibrotherm::mesh {

/// Mechanical kind of an outer edge (a label of that name marks its faces):
/// absorbing (dashpots), free, roller (zero normal displacement: a symmetry
/// plane), antisymmetric (zero tangential displacement, free normal: an
/// antisymmetry plane), fixed, source.
enum class EdgeKind { Absorbing, Free, Roller, Antisymmetric, Fixed, Source };
const char* to_string(EdgeKind kind);
/// All kinds, in label order; label names are the to_string() names.
const std::array<EdgeKind, 6>& all_edge_kinds();
/// "absorbing|free|roller|antisymmetric|fixed|source", for messages and help.
std::string edge_kind_names();

enum class Side { Bottom = 0, Right = 1, Top = 2, Left = 3 };
const char* to_string(Side side);

struct Crack {
  double x = 0.0, y = 0.0;  ///< centre [m]
  double length = 0.0;      ///< [m]
  double angle_deg = 0.0;   ///< to the horizontal, counter-clockwise
  double z = 0.0, width = 0.0;  ///< 3D: centre's z and extent along z [m]
  /// End points: centre ∓ (L/2)(cos θ, sin θ); tangent s from end 0 to end 1.
  std::array<double, 2> end(int which) const;
};

/// Shortest distance between two cracks (0 when they cross).
double crack_distance(const Crack& a, const Crack& b);

/// A transducer patch: the source acts on [center − width/2, center + width/2] of one
/// edge (measured along x on the bottom and top edges, along y on the sides); the rest
/// of that edge keeps the edge's own kind.
struct SourcePatch {
  bool on = false;
  Side side = Side::Top;
  double center = 0.0, width = 0.0;  ///< [m]
  /// The patch's ends as positions along its edge.
  double start() const { return center - 0.5 * width; }
  double end() const { return center + 0.5 * width; }
};

struct SpecimenGeometry {
  double width = 0.05, height = 0.1;
  std::vector<Crack> cracks;
  double h = 2e-3;                ///< -mesh_h: element size away from cracks
  double h_crack = 5e-4;          ///< -mesh_h_crack: element size along cracks
  double grading = 0.3;           ///< -mesh_grading: size growth per unit distance from a crack
  bool quads = true;              ///< -mesh_cell quad|tri
  std::array<EdgeKind, 4> edges = {EdgeKind::Absorbing, EdgeKind::Absorbing, EdgeKind::Source,
                                   EdgeKind::Absorbing};  ///< by Side
  double depth = 0.0;             ///< -specimen_depth: > 0 makes the specimen a 3D box
  /// -edge_front (z = D), -edge_back (z = 0) of a 3D box
  std::array<EdgeKind, 2> depth_edges = {EdgeKind::Absorbing, EdgeKind::Absorbing};
  SourcePatch patch;              ///< -source_patch_edge, -source_patch_center, -source_patch_width
  /// The patch's end points (x, y) on its edge.
  std::array<std::array<double, 2>, 2> patch_ends() const;

  /// Throws std::invalid_argument naming the option: non-positive sizes, a
  /// crack reaching beyond the specimen or lying along an edge, crossing or
  /// touching cracks, a crack with fewer than 2 elements along it.
  void validate() const;
  /// The patch lies on its edge, has a width, and the rest of its edge is not a source.
  void validate_patch() const;
  /// Whether end `which` of crack c lies on the outer boundary (within tolerance).
  bool end_on_boundary(const Crack& c, int which) const;
};

}  // namespace vibrotherm::mesh

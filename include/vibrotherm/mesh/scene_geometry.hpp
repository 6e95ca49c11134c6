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

/// The outer faces: the four edges of 2D (and of the box's x-y section), then the
/// 3D box's front (z = depth) and back (z = 0), the `side` label's values.
enum class Side { Bottom = 0, Right = 1, Top = 2, Left = 3, Front = 4, Back = 5 };
const char* to_string(Side side);
/// The axes a patch on this face is measured along (0 x, 1 y, 2 z): the 2D edge's
/// direction first (x on top/bottom and front/back, y on left/right), then z (y on front/back).
std::array<int, 2> face_axes(Side side);
/// The axis normal to this face.
int face_normal_axis(Side side);

/// A 3D crack's outline on its plane: the rectangle L × W, or the ellipse inscribed in it
/// (semi-axes L/2 along the strike, W/2 along the up-dip, z untilted; -crack_shape).
enum class CrackShape { Rectangle, Ellipse };

struct Crack {
  double x = 0.0, y = 0.0;  ///< centre [m]
  double length = 0.0;      ///< [m]
  double angle_deg = 0.0;   ///< to the horizontal, counter-clockwise
  double z = 0.0, width = 0.0;  ///< 3D: centre's z and extent along its up-dip w [m] (along z untilted)
  double tilt_deg = 0.0;        ///< 3D: -crack_tilt, the plane turned about its strike [°]
  CrackShape shape = CrackShape::Rectangle;  ///< 3D: -crack_shape
  /// 3D: the unit strike s = (cos θ, sin θ, 0), up-dip w = cos δ ẑ − sin δ n₀ and normal
  /// n = cos δ n₀ + sin δ ẑ, n₀ = (−sin θ, cos θ, 0) (δ the tilt: 0 keeps z in the plane,
  /// w = ẑ; δ > 0 turns n toward +z). The crack: centre ± (L/2) s ± (W/2) w.
  struct Axes {
    std::array<double, 3> strike, up_dip, normal;
  };
  Axes axes() const;
  /// 3D: the centre (x, y, z).
  std::array<double, 3> centre() const { return {x, y, z}; }
  /// End points: centre ∓ (L/2)(cos θ, sin θ); tangent s from end 0 to end 1.
  std::array<double, 2> end(int which) const;
  /// 3D: distance from p to the crack's rectangle (centre ± (L/2) s ± (W/2) w, axes())
  /// or to its ellipse (the elliptical disc inscribed in that rectangle).
  double distance_to(const std::array<double, 3>& p) const;
};

/// Shortest distance between two cracks (0 when they cross).
double crack_distance(const Crack& a, const Crack& b);

/// A transducer patch: the source acts on [center − width/2, center + width/2] of one
/// edge (measured along x on the bottom and top edges, along y on the sides); the rest
/// of that edge keeps the edge's own kind. 3D: the rectangle with that extent along the
/// face's first axis and [center2 − width2/2, center2 + width2/2] along its second
/// (face_axes: z on top/bottom/left/right, y on front/back).
struct SourcePatch {
  bool on = false;
  Side side = Side::Top;
  double center = 0.0, width = 0.0;    ///< [m]
  double center2 = 0.0, width2 = 0.0;  ///< 3D: along the face's second axis [m]
  /// The patch's ends as positions along its edge.
  double start() const { return center - 0.5 * width; }
  double end() const { return center + 0.5 * width; }
  /// Its bounds along face axis k (0, 1): {start, end}.
  std::array<double, 2> bounds(int k) const {
    return k == 0 ? std::array<double, 2>{start(), end()}
                  : std::array<double, 2>{center2 - 0.5 * width2, center2 + 0.5 * width2};
  }
};

struct SpecimenGeometry {
  double width = 0.05, height = 0.1;
  std::vector<Crack> cracks;
  double h = 2e-3;                ///< -mesh_h: element size away from cracks
  double h_crack = 5e-4;          ///< -mesh_h_crack: element size along cracks
  double grading = 0.3;           ///< -mesh_grading: size growth per unit distance from a crack
  bool quads = true;              ///< -mesh_cell quad|tri
  /// -mesh_crack_mirror: half-width [m] of the band around each crack meshed mirror-symmetric
  /// across it (crack_mirror.hpp; 0, the default: none; negative: DefaultMirrorWidth)
  double crack_mirror_width = 0.0;
  std::array<EdgeKind, 4> edges = {EdgeKind::Absorbing, EdgeKind::Absorbing, EdgeKind::Source,
                                   EdgeKind::Absorbing};  ///< by Side
  double depth = 0.0;             ///< -specimen_depth: > 0 makes the specimen a 3D box
  /// -edge_front (z = D), -edge_back (z = 0) of a 3D box
  std::array<EdgeKind, 2> depth_edges = {EdgeKind::Absorbing, EdgeKind::Absorbing};
  SourcePatch patch;              ///< -source_patch_edge, -source_patch_center, -source_patch_width
  /// The patch's end points (x, y) on its edge.
  std::array<std::array<double, 2>, 2> patch_ends() const;
  /// The kind of an outer face (the 2D edges, front, back).
  EdgeKind face_kind(Side side) const {
    const int s = static_cast<int>(side);
    return s < 4 ? edges[s] : depth_edges[s - 4];
  }
  /// The box's extent along axis a (0 x, 1 y, 2 z).
  double extent(int axis) const { return axis == 0 ? width : axis == 1 ? height : depth; }

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

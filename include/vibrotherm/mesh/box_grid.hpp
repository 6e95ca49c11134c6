// The structured hexahedral grid of a 3D box specimen with one or more planar cracks,
// rectangular or elliptical (the staircase of the faces whose centres lie in the ellipse),
// buried or breaking faces of the box (a crack centred on a face is cut by it: half an
// ellipse is a thumbnail crack, a quarter at an edge a corner crack; a rectangle along the
// axes may end on a face: a surface crack of that depth, or through) (plain C++,
// no PETSc): the node positions along each axis and the smooth shear that tilts grid
// planes into the crack planes.
//
// A crack: centre c, length L along its strike s = (cos θ, sin θ, 0) (θ =
// -crack_angle), width Wc along its up-dip w (z when -crack_tilt δ is 0; Crack::axes).
// Every crack of a box has its normal nearest the same axis p (y, x or z, ties in that
// order; (a, b) the two other axes, in order: (x, z) for p = y, (y, z) for x, (x, y) for z).
// Cracks on one plane x_p = c_p + m_a (x_a − c_a) + m_b (x_b − c_b) (m = −n_a/n_p,
// −n_b/n_p) share a grid plane normal to p at P = its x_p at the first crack's (x_a, x_b);
// the planes P_1 < … < P_n are sheared along p:
//   x_p' = x_p + Σ_i o_i(x_a, x_b) β_i(x_p),   o_i = m_a,i (x̄_a − ref_a) + m_b,i (x̄_b − ref_b),
// x̄ clamped to the plane's cracks' bounding boxes and 2 cells of -mesh_h_crack around
// them (beyond, the grid plane runs parallel to the axes: far less shear, so steeper cracks
// fit in a box without folding it),
// β_i = cos²(π/2 · (x_p − P_i)/d) between P_i and its neighbour plane (or the box face)
// at distance d on that side, 0 beyond (a partition: β_i = 1 on plane i, 0 on the
// others and on the two faces normal to p: the box stays a box). Each sheared plane is
// exactly its crack plane. When s and w lie along a and b (either way round) a crack is
// its bounding rectangle there, (L/2)|s_a| + (W/2)|w_a| by (L/2)|s_b| + (W/2)|w_b|, whose
// edges are grid lines; otherwise (turned and tilted) its outline is a parallelogram in
// (x_a, x_b), so like an ellipse it is the staircase of the faces of its bounding
// rectangle whose centres lie in it. Sizes: -mesh_h_crack on the
// cracks and across their planes, growing by -mesh_grading per metre of distance up to
// -mesh_h (between two cracks, from both up to half way).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

/// The sizes of a box grid: h_crack on the crack (and across its plane), growing
/// by `grading` per metre up to h. first_layer > 0 (the heat grid): across the
/// crack plane, layers from first_layer growing by `growth` up to h_crack first.
struct BoxGridSizes {
  double h_crack, h, grading;
  double first_layer = 0.0, growth = 1.0;
  /// Cells per cell of the segments' counts in the cracks' runs (the heat grid's, nested): read
  /// by AxisNodes; a BoxGrid sets it itself, ceil(the wave grid's h_crack / h_crack).
  int refine = 1;
};

/// A stretch of one axis that is meshed uniformly: [lo, hi] in `cells` cells, or a
/// crack plane (cells = 0, lo = hi) with cells of the crack's size (or layers) on
/// both sides.
struct AxisSegment {
  double lo, hi;
  int cells;
};

/// A crack's outline coordinates (along its strike and its up-dip, ±1 on its edges) from
/// its bounding rectangle's normalised in-plane coordinates (u, v) ∈ [−1, 1]² (u along the
/// grid's first in-plane axis).
struct CrackOutlineMap {
  std::array<double, 4> m{};  ///< (m0 u + m1 v, m2 u + m3 v)
  int aligned_as = 0;         ///< 1: the strike along u, exactly (u, v); 2: along v, (v, u); 0: m
  bool aligned() const { return aligned_as != 0; }
  std::array<double, 2> along_crack(const std::array<double, 2>& uv) const {
    if (aligned_as == 1) return uv;
    if (aligned_as == 2) return {uv[1], uv[0]};
    return {m[0] * uv[0] + m[1] * uv[1], m[2] * uv[0] + m[3] * uv[1]};
  }
};

class BoxGrid {
 public:
  /// Checks the 3D specimen (throws std::invalid_argument naming the option: each
  /// crack buried or breaking faces as above, never the faces its plane is parallel to
  /// (they stay flat), a corner crack along the axes, resolved by 2 cells
  /// along each extent it has a front across; the cracks apart from each other, their
  /// normals nearest one axis; a shear that does not fold the mesh) and builds the
  /// node positions along each axis.
  explicit BoxGrid(const SpecimenGeometry& geometry);
  /// The same cracks and box with other sizes (the heat grid).
  BoxGrid(const SpecimenGeometry& geometry, const BoxGridSizes& sizes);

  /// Cells along axis a.
  int cells(int axis) const { return static_cast<int>(nodes_[axis].size()) - 1; }
  long total_cells() const { return long(cells(0)) * cells(1) * cells(2); }
  /// The position of grid node (i, j, k) (integer indices), sheared.
  std::array<double, 3> position(const std::array<double, 3>& index) const;
  /// The crack (0-based) that the face with index-space centroid f (one
  /// half-integer coordinate less than a cell) lies on, −1 for none: in the crack's
  /// bounding rectangle, and for an elliptical or tilted-and-turned crack in the staircase
  /// of the wave grid's faces whose centres lie in its outline.
  int crack_at(const std::array<double, 3>& f) const;
  int crack_count() const { return static_cast<int>(cracks_.size()); }
  /// Whether crack k is a staircase of its bounding rectangle's faces (an ellipse, or a
  /// rectangle tilted and turned), not that rectangle.
  bool crack_staircase(int crack) const { return cracks_.at(crack).staircase(); }
  /// Crack k's grid lines (unsheared) along the grid planes' first in-plane axis (along = 0:
  /// x, or y for planes normal to x) or second (1: z, or y for planes normal to z).
  std::vector<double> crack_nodes(int crack, int along) const;
  /// Crack k's cells along the in-plane axes (along = 0, 1 as in crack_nodes).
  int crack_cells(int along, int crack = 0) const;
  /// The area of crack k's faces [m²] (a staircase: its faces'), and of all.
  double crack_area(int crack) const;
  double crack_area() const;
  /// The number of crack k's faces.
  int crack_faces(int crack) const;
  /// The area of crack k's outline (rectangle or ellipse) inside the body: a crack centred on
  /// a face keeps half of it, one centred on an edge a quarter [m²].
  double outline_area(int crack) const { return cracks_.at(crack).outline_area; }
  /// The faces of the box that crack k breaks (none: buried).
  const std::vector<Side>& broken_faces(int crack) const { return cracks_.at(crack).breaks; }
  /// Smallest and largest grid spacing before the shear [m].
  double h_min() const;
  double h_max() const;
  /// A patch bound that stayed on a fixed grid line nearby (the crack's edge, a face):
  /// axis, requested bound, grid line (unsheared) [m].
  struct PatchSnap {
    int axis;
    double bound, line;
  };
  const std::vector<PatchSnap>& patch_snaps() const { return patch_snaps_; }

 private:
  /// A grid plane sheared into a crack plane x_p = at + Σ_k slope_k (x_k − ref_k) (k the two
  /// in-plane axes) over [lo, hi] (its cracks and 2 cells around them); beyond, x_k is
  /// clamped to [lo_k, hi_k] (the plane continues parallel to the axes).
  struct Plane {
    double at;
    std::array<double, 2> slope, ref, lo, hi;
  };
  /// A crack on the grid: its plane, its node index range along each axis (p: its
  /// plane twice), its outline.
  struct CrackOnGrid {
    int plane;
    std::array<int, 3> lo, hi;
    CrackShape shape;
    double area_per_cell;              ///< crack area per unit of in-plane cell area (1/|n_p|)
    CrackOutlineMap outline;
    /// A staircase's lattice: the wave grid's lines over its range along each in-plane axis,
    /// before a transducer patch (which may only add lines between them).
    std::array<std::vector<double>, 2> lattice;
    /// Its true centre and half extents along the in-plane axes (a snapped end moves its
    /// lattice's end, not its outline).
    std::array<double, 2> centre, half;
    /// The area of its outline inside the body (a face through its centre keeps half) [m²].
    double outline_area = 0.0;
    /// The faces it breaks (its mouth lies on them), in the order x, y, z, low before high.
    std::vector<Side> breaks;
    bool staircase() const { return shape != CrackShape::Rectangle || !outline.aligned(); }
  };
  void validate(const SpecimenGeometry& g) const;
  /// One crack's checks (`name`: " (crack k)" with several, else empty).
  void validate_crack(const SpecimenGeometry& g, const Crack& c, const std::string& name) const;
  /// Groups the cracks into planes (this->planes_), each crack's plane in *plane_of.
  void find_planes(const SpecimenGeometry& g, std::vector<int>* plane_of);
  /// The nodes of each axis and every crack's node ranges.
  void build_axes(const SpecimenGeometry& g, const BoxGridSizes& sizes, const std::vector<int>& plane_of);
  /// The shear's displacement along p at unsheared x_p and in-plane coordinates (x0, x1).
  double offset(double xp, double x0, double x1) const;
  /// Throws when the shear folds the grid (d x_p'/d x_p < 1/4 somewhere).
  void check_fold() const;
  /// Calls visit(area) for each face of crack k.
  void for_each_face(int crack, const std::function<void(double)>& visit) const;
  bool inside_outline(const CrackOnGrid& c, const std::array<double, 3>& f) const;
  /// Moves grid nodes onto the transducer patch's bounds (box_patch.cpp).
  void align_patch(const SpecimenGeometry& g);
  /// The unsheared coordinate along axis a whose node lies at `target` on the face of
  /// normal axis n at x_n = at; NaN when the shear bends that face's grid lines.
  double unsheared(int a, int n, double at, double target) const;

  std::array<std::vector<double>, 3> nodes_;
  std::vector<Plane> planes_;  ///< sorted by `at`
  std::vector<CrackOnGrid> cracks_;
  int p_ = 1;                    ///< the axis normal to the grid planes
  std::array<int, 2> in_{0, 2};  ///< the two in-plane axes, in order
  std::array<double, 3> size_{};
  std::vector<PatchSnap> patch_snaps_;
  std::array<int, 3> stand_in_{};  ///< no crack: the node of the centre plane on each axis
  int refine_ = 1;                 ///< cells per wave-grid cell in the cracks' runs (a nested heat grid: > 1)
};

/// Makes `target` a node of the sorted `nodes`: an existing node within tol (a node in
/// `fixed`: within a third of the cell), else the nearest node not in `fixed` moved there
/// (the nodes between its fixed neighbours stretched linearly), else a new node. Updates
/// the indices in `fixed`, adds the target's, returns its position. `is_line` (empty: every
/// node) names the nodes that may be moved or kept: in a grid nested in a coarser one, the
/// coarser grid's lines, so that both move the same line and a linear stretch keeps the
/// nesting; "the cell" is then the coarser grid's.
double AlignNode(std::vector<double>* nodes, std::vector<int>* fixed, double target, double tol,
                 const std::function<bool(int)>& is_line = {});

/// The 1D nodes of [0, length]: each segment's [lo, hi] in its cells (overlapping
/// segments share a run whose sub-intervals between their ends get cells no larger than
/// any covering segment's; a plane, cells = 0, gets sizes.h_crack or the layers next to
/// it), and outside them a spacing that starts at the nearest run's cell and grows by
/// sizes.grading per metre of distance up to sizes.h (between two runs, from both, meeting
/// half way). sizes.first_layer > 0: geometric layers from first_layer by sizes.growth up
/// to sizes.h_crack on each side of a plane. Each sub-interval of a run gets sizes.refine
/// times its cells (a grid nested in the one of refine 1).
std::vector<double> AxisNodes(double length, std::vector<AxisSegment> segments, const BoxGridSizes& sizes);

/// The index of the node of `nodes` nearest x (x is meant to be one).
int NearestNode(const std::vector<double>& nodes, double x);

/// Moves segment ends within `snap` of the smallest end of their group (sorted ends each
/// within `snap` of the next) onto it: one grid line, not a sliver cell. Ends on the faces
/// (0, length: a crack through the thickness) are never a target, so a buried crack stays
/// buried. Planes (cells 0) are left alone.
void SnapEnds(std::vector<AxisSegment>* segments, double snap, double length);

}  // namespace vibrotherm::mesh

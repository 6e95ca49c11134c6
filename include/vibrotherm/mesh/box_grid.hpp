// The structured hexahedral grid of a 3D box specimen with one planar rectangular
// crack, buried or through the thickness (z extent [0, D]), or a buried elliptical one
// (the staircase of the faces whose centres lie in the ellipse) (plain C++, no PETSc): the
// node positions along each axis and the smooth shear that tilts one grid plane into
// the crack plane.
//
// The crack: centre c, length L along its strike s = (cos θ, sin θ, 0) (θ =
// -crack_angle), width Wc along z, normal in the x–y plane. A grid plane through
// the centre, normal to the axis p (y when |θ| ≤ 45°, else x), is sheared along p:
//   x_p' = x_p + (x_q − c_q) · m · β(x_p),   q the other in-plane axis,
// m = tan θ (p = y) or cot θ (p = x), β = cos²(π/2 · (x_p − c_p)/d) with d the
// distance from c_p to the box face on that side (β = 1 on the plane, 0 on the two
// faces normal to p: the box stays a box, and every outer face stays in its plane).
// The sheared plane is exactly the crack plane; the crack is its rectangle
// |x_q − c_q| ≤ L|cos θ|/2 (p = y; L|sin θ|/2 for p = x), |z − c_z| ≤ Wc/2, whose
// edges are grid lines. Sizes: -mesh_h_crack on the crack and across its plane,
// growing by -mesh_grading per metre of distance up to -mesh_h.
#pragma once

#include <array>
#include <vector>

#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

/// The sizes of a box grid: h_crack on the crack (and across its plane), growing
/// by `grading` per metre up to h. first_layer > 0 (the heat grid): across the
/// crack plane, layers from first_layer growing by `growth` up to h_crack first.
struct BoxGridSizes {
  double h_crack, h, grading;
  double first_layer = 0.0, growth = 1.0;
};

class BoxGrid {
 public:
  /// Checks the 3D specimen (throws std::invalid_argument naming the option: one
  /// crack, buried in x-y, buried or through the thickness in z, resolved by 2
  /// cells along each extent it has a front across, a shear that does not fold the
  /// mesh) and builds the node positions along each axis.
  explicit BoxGrid(const SpecimenGeometry& geometry);
  /// The same crack and box with other sizes (the heat grid).
  BoxGrid(const SpecimenGeometry& geometry, const BoxGridSizes& sizes);

  /// Cells along axis a.
  int cells(int axis) const { return static_cast<int>(nodes_[axis].size()) - 1; }
  long total_cells() const { return long(cells(0)) * cells(1) * cells(2); }
  /// The position of grid node (i, j, k) (integer indices), sheared.
  std::array<double, 3> position(const std::array<double, 3>& index) const;
  /// Whether the face with index-space centroid f (one half-integer coordinate
  /// less than a cell) lies on the crack: in its rectangle, and for an elliptical
  /// crack in the staircase of the wave grid's faces whose centres lie in the ellipse.
  bool on_crack(const std::array<double, 3>& f) const;
  /// The crack's facets and its cells along strike and z.
  int crack_cells(int along) const { return along == 0 ? crack_hi_[q_] - crack_lo_[q_] : crack_hi_[2] - crack_lo_[2]; }
  /// The area of the crack's faces [m²] (an ellipse: its staircase).
  double crack_area() const;
  /// The unit normal of the crack plane (p = y: (−sin θ, cos θ, 0) up to sign).
  std::array<double, 3> normal() const { return normal_; }
  /// Whether the crack of g runs through the thickness: its z extent is [0, D]
  /// (-crack_width = -specimen_depth, centred), a plane-strain slab's crack.
  static bool through_thickness(const SpecimenGeometry& g);
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
  void validate(const SpecimenGeometry& g) const;
  double blend(double xp) const;
  bool inside_outline(const std::array<double, 3>& f) const;
  /// Moves grid nodes onto the transducer patch's bounds (box_patch.cpp).
  void align_patch(const SpecimenGeometry& g);
  /// The unsheared coordinate along axis a whose node lies at `target` on the face of
  /// normal axis n at x_n = at; NaN when the shear bends that face's grid lines.
  double unsheared(int a, int n, double at, double target) const;

  std::array<std::vector<double>, 3> nodes_;
  std::array<int, 3> crack_lo_{}, crack_hi_{};  ///< node indices of the crack's ends (p: its plane twice)
  int p_ = 1, q_ = 0;
  double slope_ = 0.0;
  std::array<double, 3> centre_{}, extent_{}, size_{}, normal_{};
  std::vector<PatchSnap> patch_snaps_;
  bool cracked_ = true;  ///< false: a box without a crack
  double strike_per_q_ = 1.0;  ///< length along the strike per unit of the in-plane grid axis q
  CrackShape shape_ = CrackShape::Rectangle;
  std::array<int, 2> outline_cells_{};  ///< the wave grid's crack cells along strike and z (the staircase)
};

/// The 1D nodes of [0, length] with the crack's segment [b_lo, b_hi] in `cells`
/// uniform cells (cells = 0: b_lo = b_hi, a plane whose neighbours get h0), and
/// outside a spacing that starts at the segment's and grows by `grading` per metre
/// of distance up to h. *lo, *hi: the node indices of b_lo and b_hi. A plane
/// (cells = 0) with first_layer > 0 gets geometric layers from first_layer by
/// `growth` up to h0 on each side before that.
/// Makes `target` a node of the sorted `nodes`: an existing node within tol (a node in
/// `fixed`: within a third of the cell), else the nearest node not in `fixed` moved there
/// (the nodes between its fixed neighbours stretched linearly), else a new node. Updates
/// the indices in `fixed`, adds the target's, returns its position.
double AlignNode(std::vector<double>* nodes, std::vector<int>* fixed, double target, double tol);

std::vector<double> GradedAxis(double length, double b_lo, double b_hi, int cells, double h0, double h, double grading,
                               int* lo, int* hi, double first_layer = 0.0, double growth = 1.0);

}  // namespace vibrotherm::mesh

// The transducer patch on a face of a 3D box, in its grid: nodes moved onto the
// patch's bounds so that its edges are grid lines and its faces exactly the
// requested rectangle (box_patch_labels.cpp labels them).
#include <algorithm>
#include <cmath>
#include <functional>

#include "vibrotherm/mesh/box_grid.hpp"

namespace vibrotherm::mesh {

double AlignNode(std::vector<double>* nodes, std::vector<int>* fixed, double target, double tol,
                 const std::function<bool(int)>& is_line) {
  std::vector<double>& x = *nodes;
  const auto is_fixed = [&](int i) { return std::find(fixed->begin(), fixed->end(), i) != fixed->end(); };
  const auto line = [&](int i) { return !is_line || is_fixed(i) || is_line(i); };
  const int last = static_cast<int>(x.size()) - 1;
  const int above = std::clamp(static_cast<int>(std::lower_bound(x.begin(), x.end(), target) - x.begin()), 1, last);
  int far = above - 1, near = above;  // the lines around the target: [x[far], x[near]] ∋ target
  while (far > 0 && !line(far)) --far;
  while (near < last && !line(near)) ++near;
  const double cell = x[near] - x[far];
  if (target - x[far] < x[near] - target) std::swap(near, far);
  // A fixed node (the crack's edge, a face, the other bound) within a third of the cell
  // stays the bound: a sliver cell would shrink the stable time step as much.
  const double reach = is_fixed(near) ? std::max(tol, cell / 3.0) : tol;
  if (std::abs(x[near] - target) <= reach) {
    if (!is_fixed(near)) x[near] = target;
    fixed->push_back(near);
    return x[near];
  }
  const int m = !is_fixed(near) ? near : !is_fixed(far) ? far : -1;
  if (m < 0) {  // both ends fixed (a patch narrower than a cell, a crack end): split the cell
    x.insert(x.begin() + above, target);
    for (int& f : *fixed) f += f >= above;
    fixed->push_back(above);
    return target;
  }
  // Stretch the nodes between m's fixed neighbours linearly: m moves by at most half a
  // cell (2/3 when the nearer end is fixed), which keeps the grading (each cell at least
  // a third of its size).
  int lo = 0, hi = last;
  for (int f : *fixed) {
    if (f < m) lo = std::max(lo, f);
    if (f > m) hi = std::min(hi, f);
  }
  const double old = x[m];
  for (int i = lo + 1; i < m; ++i) x[i] = x[lo] + (x[i] - x[lo]) * (target - x[lo]) / (old - x[lo]);
  for (int i = m + 1; i < hi; ++i) x[i] = x[hi] - (x[hi] - x[i]) * (x[hi] - target) / (x[hi] - old);
  x[m] = target;
  fixed->push_back(m);
  return target;
}

double BoxGrid::unsheared(int a, int n, double at, double target) const {
  const bool sheared = std::any_of(planes_.begin(), planes_.end(), [](const Plane& pl) { return pl.slope != std::array<double, 2>{}; });
  if (a != p_ || !sheared) return target;  // the shear moves x_p only
  // On a face normal to in-plane axis n the shear varies across the face with the other
  // in-plane axis unless no plane slopes along it (then the lines bend: NaN).
  const int k = n == in_[0] ? 0 : 1, other = 1 - k;
  if (std::any_of(planes_.begin(), planes_.end(), [other](const Plane& pl) { return pl.slope[other] != 0.0; }))
    return NAN;
  // There the shear is x_p + offset(x_p, ...), increasing (it does not fold): bisect.
  std::array<double, 2> in_plane{};
  in_plane[k] = at;
  double lo = 0.0, hi = size_[p_];
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid + offset(mid, in_plane[0], in_plane[1]) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void BoxGrid::align_patch(const SpecimenGeometry& g) {
  if (!g.patch.on) return;
  const Side side = g.patch.side;
  const int n = face_normal_axis(side);
  const bool far = side == Side::Top || side == Side::Right || side == Side::Front;
  const auto axes = face_axes(side);
  for (int k = 0; k < 2; ++k) {
    const int a = axes[k];
    // Fixed: the faces and every crack's ends (their indices follow inserted nodes).
    std::vector<int> fixed = {0, cells(a)};
    for (const CrackOnGrid& c : cracks_) fixed.push_back(c.lo[a]), fixed.push_back(c.hi[a]);
    if (cracks_.empty()) fixed.push_back(stand_in_[a]);  // the centre plane standing in for a crack
    // A staircase's lattice lines stay (its faces are decided per lattice cell): a bound
    // between two of them splits the cell.
    for (const CrackOnGrid& c : cracks_)
      for (int j = 0; j < 2; ++j)
        if (in_[j] == a)
          for (double x : c.lattice[j]) fixed.push_back(NearestNode(nodes_[a], x));
    // In a heat grid nested in the wave grid (refine_ > 1) only the wave grid's lines inside
    // a crack's range move: the stretch between them keeps the crack faces nested.
    const auto wave_line = [&](int i) {
      for (std::size_t j = 0; j < cracks_.size(); ++j) {
        const int lo = fixed[2 + 2 * j], hi = fixed[3 + 2 * j];
        if (i > lo && i < hi && (i - lo) % refine_ != 0) return false;
      }
      return true;
    };
    for (double bound : g.patch.bounds(k)) {
      const double raw = unsheared(a, n, far ? size_[n] : 0.0, bound);
      if (!std::isfinite(raw)) continue;
      const double line = AlignNode(&nodes_[a], &fixed, raw, 1e-9 * size_[a], wave_line);
      if (std::abs(line - raw) > 1e-9 * size_[a]) patch_snaps_.push_back({a, raw, line});
    }
    for (std::size_t j = 0; j < cracks_.size(); ++j) cracks_[j].lo[a] = fixed[2 + 2 * j], cracks_[j].hi[a] = fixed[3 + 2 * j];
  }
}

}  // namespace vibrotherm::mesh

#include "vibrotherm/mesh/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::mesh {
namespace {

/// Throws std::invalid_argument with the parts streamed one after the other.
template <class... Parts>
[[noreturn]] void reject(const Parts&... parts) {
  std::ostringstream msg;
  (msg << ... << parts);
  throw std::invalid_argument(msg.str());
}

/// The steps from a breakpoint over `distance`: sizes h0 + grading·d, at most h,
/// scaled to end exactly there (at least one step).
std::vector<double> GradedSteps(double distance, double h0, double h, double grading) {
  std::vector<double> steps;
  if (!(distance > 0.0)) return steps;  // the crack reaches this face (through the thickness)
  double d = 0.0;
  while (d < distance) {
    const double step = std::min(h, h0 + grading * d);
    if (d + 0.5 * step > distance && !steps.empty()) break;  // the nearer end: stop short and stretch
    steps.push_back(step);
    d += step;
  }
  if (steps.empty()) steps.push_back(distance);
  for (double& s : steps) s *= distance / d;
  return steps;
}

/// Geometric layers from `first` growing by `growth` until they reach h0, then
/// GradedSteps from there: the heat grid's layers across the crack plane.
std::vector<double> LayeredSteps(double distance, double first, double growth, double h0, double h, double grading) {
  std::vector<double> steps;
  double d = 0.0;
  for (double step = first; step < h0 && d + step < 0.5 * distance; step *= growth) {
    steps.push_back(step);
    d += step;
  }
  const std::vector<double> rest = GradedSteps(distance - d, h0, h, grading);
  steps.insert(steps.end(), rest.begin(), rest.end());
  return steps;
}

/// The number of cells of size about h across `extent` (at least 1).
int CellsAcross(double extent, double h) { return std::max(1, static_cast<int>(std::lround(extent / h))); }

/// Overlapping segments merged: the ends of every segment in it (sorted) and the
/// cells of each sub-interval between them (empty: a plane).
struct Run {
  std::vector<double> ends;
  std::vector<int> cells;
  double first_cell() const { return cells.empty() ? 0.0 : (ends[1] - ends[0]) / cells.front(); }
  double last_cell() const { return cells.empty() ? 0.0 : (ends.back() - ends[ends.size() - 2]) / cells.back(); }
};

std::vector<Run> MergeSegments(std::vector<AxisSegment> segments, int refine) {
  std::sort(segments.begin(), segments.end(), [](const AxisSegment& a, const AxisSegment& b) { return a.lo < b.lo; });
  std::vector<Run> runs;
  std::vector<std::vector<AxisSegment>> members;
  for (const AxisSegment& s : segments) {
    if (runs.empty() || s.lo > runs.back().ends.back()) runs.push_back({{s.lo}, {}}), members.push_back({});
    Run& r = runs.back();
    r.ends.push_back(s.lo), r.ends.push_back(s.hi);
    members.back().push_back(s);
    std::sort(r.ends.begin(), r.ends.end());
    r.ends.erase(std::unique(r.ends.begin(), r.ends.end()), r.ends.end());
  }
  for (std::size_t k = 0; k < runs.size(); ++k) {
    Run& r = runs[k];
    for (std::size_t j = 0; j + 1 < r.ends.size(); ++j) {
      int n = 1;  // cells no larger than any covering segment's (one segment: exactly its cells)
      for (const AxisSegment& s : members[k])
        if (s.cells > 0 && s.lo <= r.ends[j] && s.hi >= r.ends[j + 1])
          n = std::max(n, static_cast<int>(std::ceil(s.cells * (r.ends[j + 1] - r.ends[j]) / (s.hi - s.lo) - 1e-6)));
      r.cells.push_back(n * refine);  // the heat grid's cells nest in the wave grid's
    }
  }
  return runs;
}

/// Half the extent of crack c's bounding box along axis a: (L/2)|s_a| + (W/2)|w_a|.
double HalfExtent(const Crack& c, int a) {
  const Crack::Axes axes = c.axes();
  return 0.5 * c.length * std::abs(axes.strike[a]) + 0.5 * c.width * std::abs(axes.up_dip[a]);
}

/// Crack c's extent along axis a of a box [0, size] (its bounding box's), cut where it breaks
/// a face normal to a. A crack breaks a face when its centre lies on it (the face cuts it
/// through the middle: half of it lies in the body, a thumbnail; cut by two faces, a quarter:
/// a corner crack) or, when its edges are straight lines along the axes (`straight`: an
/// aligned rectangle), when its edge lies on the face (a surface crack of that depth; on both
/// faces: through). Any other crack reaching a face pokes out of the body (`outside`).
struct AxisExtent {
  double lo = 0.0, hi = 0.0;
  std::array<bool, 2> breaks{false, false};  ///< the face at 0, at size
  bool centred_on_face = false;
  bool outside = false;
  bool broken() const { return breaks[0] || breaks[1]; }
};

AxisExtent ExtentAlong(const Crack& c, double size, int a, bool straight, double tol) {
  AxisExtent e;
  const double centre = c.centre()[a], half = HalfExtent(c, a);
  e.lo = centre - half, e.hi = centre + half;
  if (std::abs(centre) <= tol) e.lo = 0.0, e.breaks[0] = e.centred_on_face = true;
  if (std::abs(centre - size) <= tol) e.hi = size, e.breaks[1] = e.centred_on_face = true;
  if (straight && std::abs(e.lo) <= tol) e.lo = 0.0, e.breaks[0] = true;
  if (straight && std::abs(e.hi - size) <= tol) e.hi = size, e.breaks[1] = true;
  e.outside = e.lo < -tol || e.hi > size + tol || (!e.breaks[0] && e.lo <= tol) || (!e.breaks[1] && e.hi >= size - tol) ||
              (e.centred_on_face && e.breaks[0] && e.breaks[1]);
  return e;
}

/// The gap between two coplanar crack rectangles (< 0: they overlap): the largest of their
/// separations along either one's strike and up-dip (separating axes: for two rectangles in a
/// plane, one of those four separates them if anything does).
double RectangleGap(const Crack& a, const Crack& b) {
  const Crack::Axes ea = a.axes(), eb = b.axes();
  const geometry::Vec3 r = geometry::Sub(a.centre(), b.centre());
  const auto half = [](const Crack& c, const Crack::Axes& e, const geometry::Vec3& u) {
    return 0.5 * c.length * std::abs(geometry::Dot(e.strike, u)) + 0.5 * c.width * std::abs(geometry::Dot(e.up_dip, u));
  };
  double gap = -INFINITY;
  for (const geometry::Vec3& u : {ea.strike, ea.up_dip, eb.strike, eb.up_dip})
    gap = std::max(gap, std::abs(geometry::Dot(r, u)) - half(a, ea, u) - half(b, eb, u));
  return gap;
}

/// The axis crack c's normal is nearest: y, else x, else z (a tie goes to the earlier).
int NormalAxis(const Crack& c) {
  const auto n = c.axes().normal;
  int p = 1;
  if (std::abs(n[0]) > std::abs(n[1]) + 2e-12) p = 0;
  if (std::abs(n[2]) > std::abs(n[p]) + 2e-12) p = 2;
  return p;
}

constexpr const char* kAxisName[3] = {"x", "y", "z"};

/// Crack c's outline coordinates from its bounding box's normalised (u, v) along the
/// in-plane axes `in`: (u, v) = (Δ_0/H_0, Δ_1/H_1) with H the box's half extents, and
/// Δ = α s + β w solved for the strike and up-dip coordinates α, β.
CrackOutlineMap OutlineOf(const Crack& c, const std::array<int, 2>& in) {
  const Crack::Axes axes = c.axes();
  const double s0 = axes.strike[in[0]], s1 = axes.strike[in[1]], w0 = axes.up_dip[in[0]], w1 = axes.up_dip[in[1]];
  CrackOutlineMap map;
  constexpr double kAligned = 1e-12;
  if (std::abs(w0) < kAligned && std::abs(s1) < kAligned) map.aligned_as = 1;
  else if (std::abs(s0) < kAligned && std::abs(w1) < kAligned) map.aligned_as = 2;
  const double h0 = HalfExtent(c, in[0]), h1 = HalfExtent(c, in[1]), det = s0 * w1 - w0 * s1;
  const double a = 0.5 * c.length * det, b = 0.5 * c.width * det;
  map.m = {w1 * h0 / a, -w0 * h1 / a, -s1 * h0 / b, s0 * h1 / b};
  return map;
}

/// ExtentAlong in the box of g, for the grid planes' in-plane axes `in`.
AxisExtent ExtentInBox(const Crack& c, const SpecimenGeometry& g, int a, const std::array<int, 2>& in) {
  const double size[3] = {g.width, g.height, g.depth};
  const bool straight = c.shape == CrackShape::Rectangle && OutlineOf(c, in).aligned();
  return ExtentAlong(c, size[a], a, straight, 1e-9 * std::max({g.width, g.height, g.depth}));
}

}  // namespace

int NearestNode(const std::vector<double>& nodes, double x) {
  const auto it = std::min_element(nodes.begin(), nodes.end(),
                                   [x](double a, double b) { return std::abs(a - x) < std::abs(b - x); });
  return static_cast<int>(it - nodes.begin());
}

void SnapEnds(std::vector<AxisSegment>* segments, double snap, double length) {
  std::vector<double> ends;
  for (const AxisSegment& s : *segments)
    for (double end : {s.lo, s.hi})
      if (end > 0.0 && end < length) ends.push_back(end);
  std::sort(ends.begin(), ends.end());
  std::vector<double> target(ends.size());
  for (std::size_t i = 0; i < ends.size(); ++i) target[i] = i > 0 && ends[i] - ends[i - 1] <= snap ? target[i - 1] : ends[i];
  for (AxisSegment& s : *segments)
    for (double* end : {&s.lo, &s.hi})
      if (s.cells > 0 && *end > 0.0 && *end < length)  // planes (cells 0) are apart already
        *end = target[std::lower_bound(ends.begin(), ends.end(), *end) - ends.begin()];
}

std::vector<double> AxisNodes(double length, std::vector<AxisSegment> segments, const BoxGridSizes& s) {
  const std::vector<Run> runs = MergeSegments(std::move(segments), s.refine);
  // Steps away from a run's end whose cell is `cell` (0: a plane, which gets h_crack or layers).
  const auto steps = [&](double distance, double cell) {
    return cell == 0.0 && s.first_layer > 0.0 ? LayeredSteps(distance, s.first_layer, s.growth, s.h_crack, s.h, s.grading)
                                              : GradedSteps(distance, cell > 0.0 ? cell : s.h_crack, s.h, s.grading);
  };
  std::vector<double> nodes = {0.0};
  const auto append = [&](const std::vector<double>& forward) {
    for (double step : forward) nodes.push_back(nodes.back() + step);
  };
  const auto append_reversed = [&](const std::vector<double>& backward) {
    for (auto it = backward.rbegin(); it != backward.rend(); ++it) nodes.push_back(nodes.back() + *it);
  };
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Run& r = runs[k];
    if (k == 0) {
      append_reversed(steps(r.ends.front(), r.first_cell()));
    } else {  // from both runs, meeting half way
      const double half = 0.5 * (r.ends.front() - runs[k - 1].ends.back());
      append(steps(half, runs[k - 1].last_cell()));
      nodes.back() = runs[k - 1].ends.back() + half;
      append_reversed(steps(half, r.first_cell()));
    }
    nodes.back() = r.ends.front();
    for (std::size_t j = 0; j < r.cells.size(); ++j)
      for (int i = 1; i <= r.cells[j]; ++i)
        nodes.push_back(i == r.cells[j] ? r.ends[j + 1] : r.ends[j] + i * ((r.ends[j + 1] - r.ends[j]) / r.cells[j]));
  }
  append(steps(length - runs.back().ends.back(), runs.back().last_cell()));
  nodes.back() = length;
  return nodes;
}

BoxGrid::BoxGrid(const SpecimenGeometry& g) : BoxGrid(g, BoxGridSizes{g.h_crack, g.h, g.grading}) {}

BoxGrid::BoxGrid(const SpecimenGeometry& g, const BoxGridSizes& sizes) {
  if (!(g.depth > 0.0) || !std::isfinite(g.depth)) reject("-specimen_depth must be > 0 for a 3D box, got ", g.depth);
  g.validate();  // sizes, and each crack's length
  size_ = {g.width, g.height, g.depth};
  for (const Crack& c : g.cracks)
    if (!(std::abs(c.tilt_deg) <= 90.0)) reject("-crack_tilt must lie in [-90, 90] degrees, got ", c.tilt_deg);
  p_ = g.cracks.empty() ? 1 : NormalAxis(g.cracks.front());
  in_ = p_ == 0 ? std::array<int, 2>{1, 2} : p_ == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
  for (const Crack& c : g.cracks)
    if (NormalAxis(c) != p_)
      reject("-crack_angle/-crack_tilt: the cracks of a 3D box must all have their normals nearest one axis (a ",
             "crack at ", c.angle_deg, " degrees tilted by ", c.tilt_deg, " is nearest ", kAxisName[NormalAxis(c)],
             ", the first crack's ", kAxisName[p_], ")");
  std::vector<int> plane_of;
  find_planes(g, &plane_of);
  validate(g);
  build_axes(g, sizes, plane_of);
  check_fold();
  align_patch(g);
}

void BoxGrid::find_planes(const SpecimenGeometry& g, std::vector<int>* plane_of) {
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  const auto rise = [](const std::array<double, 2>& m, const std::array<double, 2>& from,
                       const std::array<double, 2>& to) { return m[0] * (to[0] - from[0]) + m[1] * (to[1] - from[1]); };
  // Each plane's x_p at the first crack's in-plane coordinates: the planes' unsheared
  // positions and their spacing are compared there (one crack: its centre).
  const std::array<double, 2> ref = {g.cracks.empty() ? 0.0 : g.cracks.front().centre()[in_[0]],
                                     g.cracks.empty() ? 0.0 : g.cracks.front().centre()[in_[1]]};
  for (const Crack& c : g.cracks) {
    const auto n = c.axes().normal;
    const std::array<double, 2> slope = {-n[in_[0]] / n[p_], -n[in_[1]] / n[p_]};
    const std::array<double, 2> centre = {c.centre()[in_[0]], c.centre()[in_[1]]};
    const double cp = c.centre()[p_];
    int found = -1;
    for (std::size_t i = 0; i < planes_.size() && found < 0; ++i) {
      const Plane& pl = planes_[i];
      if (std::abs(pl.slope[0] - slope[0]) <= 1e-12 && std::abs(pl.slope[1] - slope[1]) <= 1e-12 &&
          std::abs(pl.at + rise(pl.slope, pl.ref, centre) - cp) <= tol)
        found = static_cast<int>(i);  // on that plane
    }
    if (found < 0) {
      planes_.push_back({cp + rise(slope, centre, ref), slope, ref, {INFINITY, INFINITY}, {-INFINITY, -INFINITY}});
      found = static_cast<int>(planes_.size()) - 1;
    }
    // The plane is the crack plane over its cracks' bounding boxes and 2 cells beyond.
    Plane& pl = planes_[found];
    for (int k = 0; k < 2; ++k) {
      const double half = HalfExtent(c, in_[k]) + 2.0 * g.h_crack;
      pl.lo[k] = std::min(pl.lo[k], centre[k] - half), pl.hi[k] = std::max(pl.hi[k], centre[k] + half);
    }
    plane_of->push_back(found);
  }
  // Several planes share one clamp window, the union of theirs: parallel planes then keep
  // equal offsets everywhere, so a plane's `at` (its line at the first crack's in-plane point)
  // tells where it lies against its neighbours everywhere. Each clamped to its own cracks,
  // planes side by side were compared where one of them had stopped turning (en-echelon
  // cracks were refused as folding).
  std::array<double, 2> lo = {INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY};
  for (const Plane& pl : planes_)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], pl.lo[k]), hi[k] = std::max(hi[k], pl.hi[k]);
  for (Plane& pl : planes_) pl.lo = lo, pl.hi = hi;
  if (g.cracks.empty())  // a stand-in through the centre
    planes_.push_back({0.5 * size_[p_], {0.0, 0.0}, {0.5 * size_[in_[0]], 0.5 * size_[in_[1]]}, {0.0, 0.0},
                       {size_[in_[0]], size_[in_[1]]}});
  // Sort the planes by position, renumbering the cracks' references.
  std::vector<int> order(planes_.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return planes_[a].at < planes_[b].at; });
  std::vector<Plane> sorted;
  std::vector<int> renumber(planes_.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted.push_back(planes_[order[k]]), renumber[order[k]] = static_cast<int>(k);
  planes_ = sorted;
  for (int& p : *plane_of) p = renumber[p];
}

void BoxGrid::build_axes(const SpecimenGeometry& g, const BoxGridSizes& sizes, const std::vector<int>& plane_of) {
  const bool cracked = !g.cracks.empty();
  // Without a crack a plane through the box's centre stands in for it: no cells on it,
  // no shear, no layers; every axis graded from -mesh_h on (uniform).
  BoxGridSizes s = cracked ? sizes : BoxGridSizes{sizes.h, sizes.h, sizes.grading};
  std::array<std::vector<AxisSegment>, 3> segments;
  for (const Plane& pl : planes_) segments[p_].push_back({pl.at, pl.at, 0});
  // Along a crack, a whole number of cells per wave cell, no larger than asked (the heat
  // grid's nest in the wave grid's: the same staircase, and the friction heat's sub-squares
  // exact).
  s.refine = std::max(1, static_cast<int>(std::ceil(g.h_crack / s.h_crack - 1e-9)));
  refine_ = s.refine;
  constexpr Side kFaces[3][2] = {{Side::Left, Side::Right}, {Side::Bottom, Side::Top}, {Side::Back, Side::Front}};
  for (const Crack& c : g.cracks) {
    const Crack::Axes axes = c.axes();
    cracks_.push_back({0, {}, {}, c.shape, 1.0 / std::abs(axes.normal[p_]), OutlineOf(c, in_), {},
                       {c.centre()[in_[0]], c.centre()[in_[1]]}, {HalfExtent(c, in_[0]), HalfExtent(c, in_[1])}, 0.0, {}});
    CrackOnGrid& on_grid = cracks_.back();
    on_grid.outline_area = c.length * c.width * (c.shape == CrackShape::Ellipse ? 0.25 * M_PI : 1.0);
    for (int a = 0; a < 3; ++a) {  // along p the crack is buried (validated): no segment, no cut
      const AxisExtent e = ExtentInBox(c, g, a, in_);  // cut where the crack breaks a face
      if (e.centred_on_face) on_grid.outline_area *= 0.5;
      for (int end = 0; end < 2; ++end)
        if (e.breaks[end]) on_grid.breaks.push_back(kFaces[a][end]);
      if (a == p_) continue;
      // Cells of -mesh_h_crack measured along the crack (by the larger of the strike's and
      // the up-dip's parts along this axis): the length's and the width's counts when aligned.
      const double extent = e.broken() ? e.hi - e.lo : 2.0 * HalfExtent(c, a);
      const int cells = CellsAcross(extent / std::max(std::abs(axes.strike[a]), std::abs(axes.up_dip[a])), g.h_crack);
      segments[a].push_back({e.lo, e.hi, cells});
    }
  }
  if (!cracked)
    for (int a : in_) segments[a].push_back({0.5 * size_[a], 0.5 * size_[a], 0});
  // Crack ends closer than a third of the wave grid's crack cell share a grid line.
  for (int a : in_) SnapEnds(&segments[a], g.h_crack / 3.0, size_[a]);
  for (int a = 0; a < 3; ++a) nodes_[a] = AxisNodes(size_[a], segments[a], s);
  for (int a = 0; a < 3 && !cracked; ++a) stand_in_[a] = NearestNode(nodes_[a], segments[a].front().lo);
  // A staircase is decided on the wave grid's cells in the crack's range (its lattice), so a
  // heat grid nested in them (refine) labels the same faces.
  std::array<std::vector<double>, 2> wave_nodes;
  for (int k = 0; k < 2; ++k) wave_nodes[k] = AxisNodes(size_[in_[k]], segments[in_[k]], {g.h_crack, g.h, g.grading});
  for (std::size_t k = 0; k < cracks_.size(); ++k) {
    CrackOnGrid& c = cracks_[k];
    c.plane = plane_of[k];
    c.lo[p_] = c.hi[p_] = NearestNode(nodes_[p_], planes_[c.plane].at);
    for (int j = 0; j < 2; ++j) {
      const int a = in_[j];
      const AxisSegment& seg = segments[a][k];
      c.lo[a] = NearestNode(nodes_[a], seg.lo), c.hi[a] = NearestNode(nodes_[a], seg.hi);
      const auto& w = wave_nodes[j];
      if (c.staircase()) c.lattice[j].assign(w.begin() + NearestNode(w, seg.lo), w.begin() + NearestNode(w, seg.hi) + 1);
    }
  }
}

void BoxGrid::validate_crack(const SpecimenGeometry& g, const Crack& c, const std::string& name) const {
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  if (!(c.width > 0.0) || !std::isfinite(c.width)) reject("-crack_width must be > 0 in 3D, got ", c.width, name);
  // Its bounding box (of the corners centre ± (L/2) s ± (W/2) w), cut where it breaks a face
  // (ExtentAlong); the faces normal to its grid planes' axis p stay flat, so it cannot reach those.
  std::array<AxisExtent, 3> e;
  for (int a = 0; a < 3; ++a) e[a] = ExtentInBox(c, g, a, in_);
  e[p_].outside = e[p_].outside || e[p_].broken();
  const bool outside = e[0].outside || e[1].outside || e[2].outside;
  if (outside && c.shape == CrackShape::Ellipse)
    reject("-crack_shape ellipse with -crack_center/-crack_length/-crack_width: the elliptical crack", name, " reaches "
           "the outside of the specimen; an ellipse breaks a face only when its centre lies on that face (half of it "
           "inside: a thumbnail crack; on an edge of the box: a quarter, a corner crack), extent x [",
           e[0].lo, ", ", e[0].hi, "], y [", e[1].lo, ", ", e[1].hi, "], z [", e[2].lo, ", ", e[2].hi, "]");
  if (outside)
    reject("-crack_center/-crack_length/-crack_width/-crack_angle", c.tilt_deg != 0.0 ? "/-crack_tilt" : "", ": the crack",
           name, " reaches the outside of the specimen (a 3D crack is buried, or breaks a face normal to ",
           kAxisName[in_[0]], " or ", kAxisName[in_[1]], ": centred on the face, or a rectangle along the axes with its "
           "edge on it; it cannot reach the faces normal to ", kAxisName[p_], ", its plane's axis; extent x [",
           e[0].lo, ", ", e[0].hi, "], y [", e[1].lo, ", ", e[1].hi, "], z [", e[2].lo, ", ", e[2].hi, "] in [0, ",
           g.width, "] x [0, ", g.height, "] x [0, ", g.depth, "])");
  if (e[in_[0]].centred_on_face && e[in_[1]].centred_on_face && !OutlineOf(c, in_).aligned())
    reject("-crack_angle/-crack_tilt: a corner crack (centred on an edge of the box) has its strike and up-dip along "
           "the box's axes; this one is turned and tilted", name);
  // Centred in z with -crack_width = -specimen_depth and its width mostly along z, a tilted
  // crack was meant to go through the thickness, which only an untilted one does.
  if (c.tilt_deg != 0.0 && std::abs(c.tilt_deg) < 45.0 && std::abs(c.width - g.depth) <= tol &&
      std::abs(c.z - 0.5 * g.depth) <= tol)
    reject("-crack_tilt: a crack through the thickness (-crack_width = -specimen_depth) is untilted; a tilted ",
           "crack is narrower than the depth (-crack_width < -specimen_depth)", name);
  // Cells across the part in the body, along the strike and along the up-dip.
  const Crack::Axes axes = c.axes();
  const auto axis_of = [&](const std::array<double, 3>& along) {  // the in-plane axis it runs along most
    return std::abs(along[in_[0]]) >= std::abs(along[in_[1]]) ? in_[0] : in_[1];
  };
  const auto kept = [&](const std::array<double, 3>& along) {  // the fraction of it in the body
    const int a = axis_of(along);
    return e[a].broken() ? (e[a].hi - e[a].lo) / (2.0 * HalfExtent(c, a)) : 1.0;
  };
  const AxisExtent& up_dip = e[axis_of(axes.up_dip)];
  const bool through = up_dip.breaks[0] && up_dip.breaks[1];  // no front across its width
  const int along = CellsAcross(c.length * kept(axes.strike), g.h_crack);
  const int across = CellsAcross(c.width * kept(axes.up_dip), g.h_crack);
  if (along < 2)
    reject("-crack_length ", c.length, " m is resolved by fewer than 2 cells of -mesh_h_crack ", g.h_crack, " m", name);
  const bool staircase = c.shape == CrackShape::Ellipse || !OutlineOf(c, in_).aligned();
  if (staircase && std::min(along, across) < 4)
    reject(c.shape == CrackShape::Ellipse ? "-crack_shape ellipse: the ellipse" : "-crack_tilt with -crack_angle: the "
           "staircase of a tilted, turned crack", " needs at least 4 cells of -mesh_h_crack ", g.h_crack,
           " m across each axis (fewer make it its rectangle), got ", along, " x ", across, name);
  if (across < 2 && !through)
    reject("-crack_width ", c.width, " m is resolved by fewer than 2 cells of -mesh_h_crack ", g.h_crack, " m", name);
}

void BoxGrid::validate(const SpecimenGeometry& g) const {
  for (std::size_t k = 0; k < g.cracks.size(); ++k)
    validate_crack(g, g.cracks[k], g.cracks.size() > 1 ? " (crack " + std::to_string(k + 1) + ")" : std::string());
  for (std::size_t i = 1; i < planes_.size(); ++i)
    if (planes_[i].at - planes_[i - 1].at < 2.0 * g.h_crack * (1.0 - 1e-9))
      reject("-crack_center/-crack_angle/-crack_tilt: two crack planes lie ", planes_[i].at - planes_[i - 1].at,
             " m apart along ", kAxisName[p_], " (at ", kAxisName[in_[0]], " = ", planes_[i].ref[0], " m, ",
             kAxisName[in_[1]], " = ", planes_[i].ref[1], " m); they need at least 2 ",
             "cells of -mesh_h_crack (", g.h_crack, " m) between them, and cracks sharing a plane must lie exactly in it");
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {  // on one plane (the others are apart): their rectangles must not touch
      const Crack &a = g.cracks[i], &b = g.cracks[j];
      const double normal = std::abs(geometry::Dot(geometry::Sub(a.centre(), b.centre()), a.axes().normal));
      const double gap = RectangleGap(a, b);
      if (normal < 2.0 * g.h_crack && gap < g.h_crack * (1.0 - 1e-9))
        reject("-crack_center: cracks ", j + 1, " and ", i + 1, " overlap or come closer than one cell of ",
               "-mesh_h_crack (", g.h_crack, " m) on their plane (gap ", gap, " m)");
    }
}

double BoxGrid::offset(double xp, double x0, double x1) const {
  // Plane i's offset o_i(x_a, x_b) weighted by cos² of the way to its neighbour (or the face).
  const auto above = std::upper_bound(planes_.begin(), planes_.end(), xp,
                                      [](double x, const Plane& pl) { return x < pl.at; });
  const auto weight = [&](const Plane& pl, double d) {
    const double c = std::cos(0.5 * M_PI * (xp - pl.at) / d);
    const double y0 = std::clamp(x0, pl.lo[0], pl.hi[0]), y1 = std::clamp(x1, pl.lo[1], pl.hi[1]);
    return ((y0 - pl.ref[0]) * pl.slope[0] + (y1 - pl.ref[1]) * pl.slope[1]) * (c * c);
  };
  double shift = 0.0;
  if (above != planes_.begin()) {  // the plane below x_p, toward the next one up (or the face)
    const Plane& pl = *(above - 1);
    shift += weight(pl, (above == planes_.end() ? size_[p_] : above->at) - pl.at);
  }
  if (above != planes_.end()) {  // the plane above, toward the one below (or the face at 0)
    const Plane& pl = *above;
    shift += weight(pl, pl.at - (above == planes_.begin() ? 0.0 : (above - 1)->at));
  }
  return shift;
}

void BoxGrid::check_fold() const {
  // The shear is piecewise linear in the in-plane coordinates (linear between the planes'
  // clamps), so d x_p'/d x_p is extreme on the lines along p through the faces and the clamps.
  std::array<std::vector<double>, 2> lines;
  for (int k = 0; k < 2; ++k) {
    lines[k] = {0.0, size_[in_[k]]};
    for (const Plane& pl : planes_)
      for (double x : {pl.lo[k], pl.hi[k]})
        if (x > 0.0 && x < size_[in_[k]]) lines[k].push_back(x);
  }
  constexpr int kSamples = 4000;
  const double dx = size_[p_] / kSamples;
  for (double x0 : lines[0])
    for (double x1 : lines[1])
      for (int i = 0; i < kSamples; ++i) {
        const double a = i * dx, b = a + dx;
        if (1.0 + (offset(b, x0, x1) - offset(a, x0, x1)) / dx < 0.25)
          reject("-crack_angle/-crack_tilt/-crack_center: the 3D grid cannot be sheared into the crack plane",
                 planes_.size() > 1 ? "s" : "", " without folding (near ", kAxisName[p_], " = ", a, " m on the line ",
                 kAxisName[in_[0]], " = ", x0, " m, ", kAxisName[in_[1]], " = ", x1, " m): a smaller inclination, ",
                 "or the cracks farther from each other and from the faces normal to ", kAxisName[p_]);
      }
}

std::array<double, 3> BoxGrid::position(const std::array<double, 3>& index) const {
  std::array<double, 3> x;
  for (int a = 0; a < 3; ++a) x[a] = nodes_[a][static_cast<std::size_t>(std::lround(index[a]))];
  x[p_] += offset(x[p_], x[in_[0]], x[in_[1]]);
  return x;
}

int BoxGrid::crack_at(const std::array<double, 3>& f) const {
  for (std::size_t k = 0; k < cracks_.size(); ++k) {
    const CrackOnGrid& c = cracks_[k];
    const auto inside = [&](int a) { return f[a] > c.lo[a] && f[a] < c.hi[a]; };
    if (std::abs(f[p_] - c.lo[p_]) < 1e-9 && inside(in_[0]) && inside(in_[1]) && inside_outline(c, f))
      return static_cast<int>(k);
  }
  return -1;
}

bool BoxGrid::inside_outline(const CrackOnGrid& c, const std::array<double, 3>& f) const {
  if (!c.staircase()) return true;
  // The face is kept when the lattice cell (the wave grid's, by position) holding its centre
  // has its centre in the outline: the wave grid and a heat grid nested in it agree.
  std::array<double, 2> uv;
  for (int k = 0; k < 2; ++k) {
    const int a = in_[k];
    const std::size_t i = static_cast<std::size_t>(std::floor(f[a]));
    const double x = 0.5 * (nodes_[a][i] + nodes_[a][std::min(i + 1, nodes_[a].size() - 1)]);
    const std::vector<double>& lattice = c.lattice[k];
    const std::size_t cell = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(lattice.begin(), lattice.end(), x) - lattice.begin()), 1,
        lattice.size() - 1);
    const double centre = 0.5 * (lattice[cell - 1] + lattice[cell]);
    uv[k] = (centre - c.centre[k]) / c.half[k];
  }
  const auto [s, w] = c.outline.along_crack(uv);  // along the strike and the up-dip, ±1 on the edges
  if (c.shape == CrackShape::Ellipse) return s * s + w * w <= 1.0;
  return std::abs(s) <= 1.0 && std::abs(w) <= 1.0;
}

std::vector<double> BoxGrid::crack_nodes(int crack, int along) const {
  const CrackOnGrid& c = cracks_.at(crack);
  const int a = in_[along];
  return {nodes_[a].begin() + c.lo[a], nodes_[a].begin() + c.hi[a] + 1};
}

int BoxGrid::crack_cells(int along, int crack) const {
  const CrackOnGrid& c = cracks_.at(crack);
  const int a = in_[along];
  return c.hi[a] - c.lo[a];
}

void BoxGrid::for_each_face(int crack, const std::function<void(double)>& visit) const {
  const CrackOnGrid& c = cracks_.at(crack);
  const int a0 = in_[0], a1 = in_[1];
  for (int i = c.lo[a0]; i < c.hi[a0]; ++i)
    for (int j = c.lo[a1]; j < c.hi[a1]; ++j) {
      std::array<double, 3> f{};
      f[p_] = c.lo[p_], f[a0] = i + 0.5, f[a1] = j + 0.5;
      if (crack_at(f) == crack) visit((nodes_[a0][i + 1] - nodes_[a0][i]) * c.area_per_cell * (nodes_[a1][j + 1] - nodes_[a1][j]));
    }
}

double BoxGrid::crack_area(int crack) const {
  double area = 0.0;
  for_each_face(crack, [&](double face) { area += face; });
  return area;
}

int BoxGrid::crack_faces(int crack) const {
  int faces = 0;
  for_each_face(crack, [&](double) { ++faces; });
  return faces;
}

double BoxGrid::crack_area() const {
  double area = 0.0;
  for (int k = 0; k < crack_count(); ++k) area += crack_area(k);
  return area;
}

double BoxGrid::h_min() const {
  double h = INFINITY;
  for (const auto& axis : nodes_)
    for (std::size_t k = 1; k < axis.size(); ++k) h = std::min(h, axis[k] - axis[k - 1]);
  return h;
}

double BoxGrid::h_max() const {
  double h = 0.0;
  for (const auto& axis : nodes_)
    for (std::size_t k = 1; k < axis.size(); ++k) h = std::max(h, axis[k] - axis[k - 1]);
  return h;
}

}  // namespace vibrotherm::mesh

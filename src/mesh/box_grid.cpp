#include "vibrotherm/mesh/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

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

std::vector<Run> MergeSegments(std::vector<AxisSegment> segments) {
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
      r.cells.push_back(n);
    }
  }
  return runs;
}

/// Half the extent of crack c's bounding box along axis a: (L/2)|s_a| + (W/2)|w_a|.
double HalfExtent(const Crack& c, int a) {
  const Crack::Axes axes = c.axes();
  return 0.5 * c.length * std::abs(axes.strike[a]) + 0.5 * c.width * std::abs(axes.up_dip[a]);
}

/// The index of the node at x (it must be one).
int NodeAt(const std::vector<double>& nodes, double x) {
  const auto it = std::min_element(nodes.begin(), nodes.end(),
                                   [x](double a, double b) { return std::abs(a - x) < std::abs(b - x); });
  return static_cast<int>(it - nodes.begin());
}

}  // namespace

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
  const std::vector<Run> runs = MergeSegments(std::move(segments));
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
  g.validate();  // sizes, and each crack's trace in the x-y plane
  size_ = {g.width, g.height, g.depth};
  const auto steep = [](const Crack& c) { return std::abs(std::cos(c.angle_deg * M_PI / 180.0)) < std::sqrt(0.5) - 1e-12; };
  p_ = !g.cracks.empty() && steep(g.cracks.front()) ? 0 : 1;
  q_ = 1 - p_;
  for (const Crack& c : g.cracks)
    if (!(std::abs(c.tilt_deg) <= 45.0))
      reject("-crack_tilt must lie in [-45, 45] degrees (the crack's normal nearest the x-y plane), got ", c.tilt_deg);
  for (const Crack& c : g.cracks)
    if ((steep(c) ? 0 : 1) != p_)
      reject("-crack_angle: the cracks of a 3D box must all be within 45 degrees of horizontal, or all steeper (",
             c.angle_deg, " and ", g.cracks.front().angle_deg, " given)");
  std::vector<int> plane_of;
  find_planes(g, &plane_of);
  validate(g);
  build_axes(g, sizes, plane_of);
  check_fold();
  align_patch(g);
}

void BoxGrid::find_planes(const SpecimenGeometry& g, std::vector<int>* plane_of) {
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  for (const Crack& c : g.cracks) {
    const auto n = c.axes().normal;
    const double slope = -n[q_] / n[p_], slope_z = -n[2] / n[p_];
    const double cp = p_ == 0 ? c.x : c.y, cq = p_ == 0 ? c.y : c.x;
    int found = -1;
    for (std::size_t i = 0; i < planes_.size() && found < 0; ++i) {
      const Plane& pl = planes_[i];
      if (std::abs(pl.slope - slope) <= 1e-12 && std::abs(pl.slope_z - slope_z) <= 1e-12 &&
          std::abs(pl.at + pl.slope * (cq - pl.q0) + pl.slope_z * (c.z - pl.z0) - cp) <= tol)
        found = static_cast<int>(i);  // on that plane
    }
    // Each plane's x_p at the first crack's (x_q, z): the planes' unsheared positions and
    // their spacing are compared there (one crack: its centre).
    const Crack& first = g.cracks.front();
    const double q_ref = p_ == 0 ? first.y : first.x;
    if (found < 0) {
      planes_.push_back({cp + slope * (q_ref - cq) + slope_z * (first.z - c.z), slope, q_ref, slope_z, first.z,
                         {INFINITY, INFINITY}, {-INFINITY, -INFINITY}});
      found = static_cast<int>(planes_.size()) - 1;
    }
    // The plane is the crack plane over its cracks' bounding boxes and 2 cells beyond.
    Plane& pl = planes_[found];
    const double margin = 2.0 * g.h_crack, centre[2] = {cq, c.z};
    for (int k = 0; k < 2; ++k) {
      const double half = HalfExtent(c, k == 0 ? q_ : 2) + margin;
      pl.lo[k] = std::min(pl.lo[k], centre[k] - half), pl.hi[k] = std::max(pl.hi[k], centre[k] + half);
    }
    plane_of->push_back(found);
  }
  if (g.cracks.empty())  // a stand-in through the centre
    planes_.push_back({0.5 * size_[p_], 0.0, 0.5 * size_[q_], 0.0, 0.5 * size_[2], {0.0, 0.0}, {size_[q_], size_[2]}});
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
  const BoxGridSizes s = cracked ? sizes : BoxGridSizes{sizes.h, sizes.h, sizes.grading};
  std::array<std::vector<AxisSegment>, 3> segments;
  for (const Plane& pl : planes_) segments[p_].push_back({pl.at, pl.at, 0});
  // Along a crack, a whole number of cells per wave cell (the heat grid's nest in the wave
  // grid's: the same staircase, and the friction heat's sub-squares exact).
  const int per_wave_cell = std::max(1, static_cast<int>(std::lround(g.h_crack / s.h_crack)));
  for (const Crack& c : g.cracks) {
    const Crack::Axes axes = c.axes();
    const double sq = axes.strike[q_], wq = axes.up_dip[q_];  // the strike's and up-dip's parts along q
    const double half_q = HalfExtent(c, q_), cq = q_ == 0 ? c.x : c.y;
    const double along_strike = 2.0 * half_q / std::abs(sq);  // the bounding rectangle's extent along the strike
    segments[q_].push_back({cq - half_q, cq + half_q, per_wave_cell * CellsAcross(along_strike, g.h_crack)});
    const bool through = through_thickness(c, g);  // ends exactly on the faces
    const double half_z = HalfExtent(c, 2);
    const double z0 = through ? 0.0 : c.z - half_z, z1 = through ? g.depth : c.z + half_z;
    segments[2].push_back({z0, z1, per_wave_cell * CellsAcross(c.width, g.h_crack)});
    const double stretch = half_q / (0.5 * c.length * sq), skew = -c.width * wq / (c.length * sq);
    cracks_.push_back({0, {}, {}, c.shape, {CellsAcross(along_strike, g.h_crack), CellsAcross(c.width, g.h_crack)},
                       1.0 / std::abs(axes.normal[p_]), stretch, skew});
  }
  if (!cracked) segments[q_].push_back({0.5 * size_[q_], 0.5 * size_[q_], 0}), segments[2].push_back({0.5 * size_[2], 0.5 * size_[2], 0});
  // Crack ends closer than a third of the wave grid's crack cell share a grid line.
  for (int a : {q_, 2}) SnapEnds(&segments[a], g.h_crack / 3.0, size_[a]);
  for (int a = 0; a < 3; ++a) nodes_[a] = AxisNodes(size_[a], segments[a], s);
  for (int a = 0; a < 3 && !cracked; ++a) stand_in_[a] = NodeAt(nodes_[a], segments[a].front().lo);
  for (std::size_t k = 0; k < cracks_.size(); ++k) {
    CrackOnGrid& c = cracks_[k];
    c.plane = plane_of[k];
    c.lo[p_] = c.hi[p_] = NodeAt(nodes_[p_], planes_[c.plane].at);
    for (int a : {q_, 2}) {
      const AxisSegment& seg = segments[a][k];
      c.lo[a] = NodeAt(nodes_[a], seg.lo), c.hi[a] = NodeAt(nodes_[a], seg.hi);
    }
  }
}

void BoxGrid::validate_crack(const SpecimenGeometry& g, const Crack& c, const std::string& name) const {
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  if (!(c.width > 0.0) || !std::isfinite(c.width)) reject("-crack_width must be > 0 in 3D, got ", c.width, name);
  // Its corners centre ± (L/2) s ± (W/2) w: buried in x-y; in z buried, or exactly [0, D]
  // (through the thickness, untilted: a plane-strain slab's crack).
  const Crack::Axes axes = c.axes();
  std::array<double, 3> lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
  for (double i : {-0.5, 0.5})
    for (double j : {-0.5, 0.5})
      for (int a = 0; a < 3; ++a) {
        const double x = (a == 0 ? c.x : a == 1 ? c.y : c.z) + i * c.length * axes.strike[a] + j * c.width * axes.up_dip[a];
        lo[a] = std::min(lo[a], x), hi[a] = std::max(hi[a], x);
      }
  const bool inside_box = std::min(lo[0], lo[1]) > tol && hi[0] < g.width - tol && hi[1] < g.height - tol;
  const bool through = through_thickness(c, g), z_ok = (lo[2] > tol && hi[2] < g.depth - tol) || through;
  if (!inside_box || !z_ok)
    reject("-crack_center/-crack_length/-crack_width", c.tilt_deg != 0.0 ? "/-crack_tilt" : "", ": the crack",
           name, " reaches the outside of the specimen (3D cracks must be buried in x-y and either buried in z or ",
           "through the thickness, untilted with -crack_width = -specimen_depth centred at z = depth/2; extent x [",
           lo[0], ", ", hi[0], "], y [", lo[1], ", ", hi[1], "], z [", lo[2], ", ", hi[2], "] in [0, ", g.width,
           "] x [0, ", g.height, "] x [0, ", g.depth, "])");
  if (c.shape == CrackShape::Ellipse && through)
    reject("-crack_shape ellipse: an elliptical crack must be buried (-crack_width < -specimen_depth); a crack ",
           "through the thickness is a rectangle");
  const int along = CellsAcross(c.length, g.h_crack), across = CellsAcross(c.width, g.h_crack);
  if (along < 2)
    reject("-crack_length ", c.length, " m is resolved by fewer than 2 cells of -mesh_h_crack ", g.h_crack, " m", name);
  const bool staircase = c.shape == CrackShape::Ellipse || axes.up_dip[q_] != 0.0;
  if (staircase && std::min(along, across) < 4)
    reject(c.shape == CrackShape::Ellipse ? "-crack_shape ellipse: the ellipse" : "-crack_tilt with -crack_angle: the "
           "staircase of a tilted, turned crack", " needs at least 4 cells of -mesh_h_crack ", g.h_crack,
           " m across each axis (fewer make it its rectangle), got ", along, " x ", across, name);
  if (across < 2 && !through)  // a through crack has no front along z
    reject("-crack_width ", c.width, " m is resolved by fewer than 2 cells of -mesh_h_crack ", g.h_crack, " m", name);
}

void BoxGrid::validate(const SpecimenGeometry& g) const {
  for (std::size_t k = 0; k < g.cracks.size(); ++k)
    validate_crack(g, g.cracks[k], g.cracks.size() > 1 ? " (crack " + std::to_string(k + 1) + ")" : std::string());
  for (std::size_t i = 1; i < planes_.size(); ++i)
    if (planes_[i].at - planes_[i - 1].at < 2.0 * g.h_crack * (1.0 - 1e-9))
      reject("-crack_center/-crack_angle: two crack planes lie ", planes_[i].at - planes_[i - 1].at, " m apart along ",
             p_ == 0 ? "x" : "y", " (at ", q_ == 0 ? "x" : "y", " = ", planes_[i].q0, " m); they need at least 2 ",
             "cells of -mesh_h_crack (", g.h_crack, " m) between them, and two cracks on one plane must lie on one line");
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {  // on one plane (the others are apart): their rectangles must not touch
      const Crack &a = g.cracks[i], &b = g.cracks[j];
      const Crack::Axes axes = a.axes();
      const std::array<double, 3> r = {a.x - b.x, a.y - b.y, a.z - b.z};
      const auto dot = [&r](const std::array<double, 3>& u) { return std::abs(r[0] * u[0] + r[1] * u[1] + r[2] * u[2]); };
      const double along = dot(axes.strike), up = dot(axes.up_dip), normal = dot(axes.normal);
      const double gap = std::max(along - 0.5 * (a.length + b.length), up - 0.5 * (a.width + b.width));
      if (normal < 2.0 * g.h_crack && gap < g.h_crack * (1.0 - 1e-9))
        reject("-crack_center: cracks ", j + 1, " and ", i + 1, " overlap or come closer than one cell of ",
               "-mesh_h_crack (", g.h_crack, " m) on their plane (gap ", gap, " m)");
    }
}

bool BoxGrid::through_thickness(const Crack& c, const SpecimenGeometry& g) {
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  return c.tilt_deg == 0.0 && std::abs(c.z - 0.5 * c.width) <= tol && std::abs(c.z + 0.5 * c.width - g.depth) <= tol;
}

double BoxGrid::offset(double xp, double xq, double z) const {
  // Plane i's offset o_i(x_q) weighted by cos² of the way to its neighbour (or the face).
  const auto above = std::upper_bound(planes_.begin(), planes_.end(), xp,
                                      [](double x, const Plane& pl) { return x < pl.at; });
  const auto weight = [&](const Plane& pl, double d) {
    const double c = std::cos(0.5 * M_PI * (xp - pl.at) / d);
    const double q = std::clamp(xq, pl.lo[0], pl.hi[0]), zc = std::clamp(z, pl.lo[1], pl.hi[1]);
    return ((q - pl.q0) * pl.slope + (zc - pl.z0) * pl.slope_z) * (c * c);
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
  // The shear is piecewise linear in x_q and z (linear between the planes' clamps), so
  // d x_p'/d x_p is extreme on the lines along p through the faces and the clamps.
  std::vector<double> qs = {0.0, size_[q_]}, zs = {0.0, size_[2]};
  for (const Plane& pl : planes_)
    qs.insert(qs.end(), {pl.lo[0], pl.hi[0]}), zs.insert(zs.end(), {pl.lo[1], pl.hi[1]});
  constexpr int kSamples = 4000;
  for (double xq : qs)
    for (double z : zs) {
      if (xq < 0.0 || xq > size_[q_] || z < 0.0 || z > size_[2]) continue;
      const double dx = size_[p_] / kSamples;
      for (int i = 0; i < kSamples; ++i) {
        const double x0 = i * dx, x1 = x0 + dx;
        const double stretch = 1.0 + (offset(x1, xq, z) - offset(x0, xq, z)) / dx;
        if (stretch < 0.25)
          reject("-crack_angle/-crack_tilt/-crack_center: the 3D grid cannot be sheared into the crack plane",
                 planes_.size() > 1 ? "s" : "", " without folding (near ", p_ == 0 ? "x" : "y", " = ", x0,
                 " m on the line ", q_ == 0 ? "x" : "y", " = ", xq, " m, z = ", z, " m): a smaller inclination, or ",
                 "the cracks farther from each other and from the faces normal to ", p_ == 0 ? "x" : "y");
      }
    }
}

std::array<double, 3> BoxGrid::position(const std::array<double, 3>& index) const {
  std::array<double, 3> x;
  for (int a = 0; a < 3; ++a) x[a] = nodes_[a][static_cast<std::size_t>(std::lround(index[a]))];
  x[p_] += offset(x[p_], x[q_], x[2]);
  return x;
}

int BoxGrid::crack_at(const std::array<double, 3>& f) const {
  for (std::size_t k = 0; k < cracks_.size(); ++k) {
    const CrackOnGrid& c = cracks_[k];
    const auto inside = [&](int a) { return f[a] > c.lo[a] && f[a] < c.hi[a]; };
    if (std::abs(f[p_] - c.lo[p_]) < 1e-9 && inside(q_) && inside(2) && inside_outline(c, f)) return static_cast<int>(k);
  }
  return -1;
}

bool BoxGrid::inside_outline(const CrackOnGrid& c, const std::array<double, 3>& f) const {
  if (!c.staircase()) return true;
  // The crack's bounding rectangle cut into the wave grid's uniform crack cells: the face
  // is kept when the cell holding its centre (by position, so that the wave grid and the
  // finer heat grid nested in it agree) has its centre in the outline.
  const int axes[2] = {q_, 2};
  double uv[2];
  for (int k = 0; k < 2; ++k) {
    const int a = axes[k];
    const std::size_t i = static_cast<std::size_t>(std::floor(f[a]));
    const double x = 0.5 * (nodes_[a][i] + nodes_[a][std::min(i + 1, nodes_[a].size() - 1)]);
    const double lo = nodes_[a][c.lo[a]], hi = nodes_[a][c.hi[a]];
    const double cell = std::floor((x - lo) / (hi - lo) * c.outline_cells[k]);
    uv[k] = 2.0 * (cell + 0.5) / c.outline_cells[k] - 1.0;
  }
  // Along the strike and the up-dip, ±1 on the outline's edges.
  const double s = c.skew == 0.0 ? uv[0] : c.stretch * uv[0] + c.skew * uv[1], w = uv[1];
  if (c.shape == CrackShape::Ellipse) return s * s + w * w <= 1.0;
  return std::abs(s) <= 1.0 && std::abs(w) <= 1.0;
}

std::vector<double> BoxGrid::crack_nodes(int crack, int along) const {
  const CrackOnGrid& c = cracks_.at(crack);
  const int a = along == 0 ? q_ : 2;
  return {nodes_[a].begin() + c.lo[a], nodes_[a].begin() + c.hi[a] + 1};
}

int BoxGrid::crack_cells(int along, int crack) const {
  const CrackOnGrid& c = cracks_.at(crack);
  const int a = along == 0 ? q_ : 2;
  return c.hi[a] - c.lo[a];
}

void BoxGrid::for_each_face(int crack, const std::function<void(double)>& visit) const {
  const CrackOnGrid& c = cracks_.at(crack);
  for (int i = c.lo[q_]; i < c.hi[q_]; ++i)
    for (int j = c.lo[2]; j < c.hi[2]; ++j) {
      std::array<double, 3> f{};
      f[p_] = c.lo[p_], f[q_] = i + 0.5, f[2] = j + 0.5;
      if (crack_at(f) == crack) visit((nodes_[q_][i + 1] - nodes_[q_][i]) * c.area_per_qz * (nodes_[2][j + 1] - nodes_[2][j]));
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

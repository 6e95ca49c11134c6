#include "vibrotherm/mesh/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::mesh {

const char* to_string(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::Absorbing: return "absorbing";
    case EdgeKind::Free: return "free";
    case EdgeKind::Roller: return "roller";
    case EdgeKind::Antisymmetric: return "antisymmetric";
    case EdgeKind::Fixed: return "fixed";
    case EdgeKind::Source: return "source";
  }
  return "?";
}

const std::array<EdgeKind, 6>& all_edge_kinds() {
  static const std::array<EdgeKind, 6> kinds = {EdgeKind::Absorbing, EdgeKind::Free,  EdgeKind::Roller,
                                                EdgeKind::Antisymmetric, EdgeKind::Fixed, EdgeKind::Source};
  return kinds;
}

std::string edge_kind_names() {
  std::string names;
  for (EdgeKind k : all_edge_kinds()) names += (names.empty() ? "" : "|") + std::string(to_string(k));
  return names;
}

const char* to_string(Side side) {
  switch (side) {
    case Side::Bottom: return "bottom";
    case Side::Right: return "right";
    case Side::Top: return "top";
    case Side::Left: return "left";
    case Side::Front: return "front";
    case Side::Back: return "back";
  }
  return "?";
}

std::array<int, 2> face_axes(Side side) {
  switch (side) {
    case Side::Bottom:
    case Side::Top: return {0, 2};
    case Side::Left:
    case Side::Right: return {1, 2};
    default: return {0, 1};
  }
}

int face_normal_axis(Side side) {
  const auto a = face_axes(side);
  return 3 - a[0] - a[1];
}

std::array<double, 2> Crack::end(int which) const {
  const double t = angle_deg * M_PI / 180.0, sign = which == 0 ? -0.5 : 0.5;
  return {x + sign * length * std::cos(t), y + sign * length * std::sin(t)};
}

namespace {

[[noreturn]] void reject(const std::string& text) { throw std::invalid_argument(text); }

double tolerance(const SpecimenGeometry& g) { return 1e-9 * std::max(g.width, g.height); }

/// Orientation of the triangle (p, q, r): > 0 counter-clockwise.
double orient(const std::array<double, 2>& p, const std::array<double, 2>& q, const std::array<double, 2>& r) {
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

/// In-plane distance from (s, t) to the elliptical disc s²/a² + t²/b² ≤ 1: 0 inside,
/// else to the nearest point (a cos φ, b sin φ), found by sampling φ and refining by
/// golden sections (the distance is unimodal near its minimum).
double DistanceToEllipse(double a, double b, double s, double t) {
  if ((s * s) / (a * a) + (t * t) / (b * b) <= 1.0) return 0.0;
  const auto d2 = [&](double phi) { return std::pow(a * std::cos(phi) - s, 2) + std::pow(b * std::sin(phi) - t, 2); };
  constexpr int kSamples = 256;
  double best = 0.0;
  for (int k = 1; k < kSamples; ++k)
    if (d2(2 * M_PI * k / kSamples) < d2(best)) best = 2 * M_PI * k / kSamples;
  double lo = best - 2 * M_PI / kSamples, hi = best + 2 * M_PI / kSamples;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
    if (d2(m1) < d2(m2)) hi = m2;
    else lo = m1;
  }
  return std::sqrt(d2(0.5 * (lo + hi)));
}

/// cos and sin of an angle in degrees, exact at multiples of 90° (cos 90° is 6e-17 in
/// radians: a crack parallel to a face must have exactly zero slopes, not a shear of 1e-17).
std::array<double, 2> CosSinDegrees(double degrees) {
  const double quarter = degrees / 90.0;
  if (quarter == std::round(quarter)) {
    static constexpr double kCos[4] = {1.0, 0.0, -1.0, 0.0}, kSin[4] = {0.0, 1.0, 0.0, -1.0};
    const int k = ((static_cast<int>(std::lround(std::fmod(quarter, 4.0))) % 4) + 4) % 4;
    return {kCos[k], kSin[k]};
  }
  const double r = degrees * M_PI / 180.0;
  return {std::cos(r), std::sin(r)};
}

}  // namespace

Crack::Axes Crack::axes() const {
  const auto [ct, st] = CosSinDegrees(angle_deg);
  const auto [cd, sd] = CosSinDegrees(tilt_deg);
  const std::array<double, 3> n0 = {-st, ct, 0.0};
  return {{ct, st, 0.0}, {-sd * n0[0], -sd * n0[1], cd}, {cd * n0[0], cd * n0[1], sd}};
}

double Crack::distance_to(const std::array<double, 3>& p) const {
  const Axes a = axes();
  const geometry::Vec3 r = geometry::Sub(p, centre());
  const double along = geometry::Dot(r, a.strike), up = geometry::Dot(r, a.up_dip), normal = geometry::Dot(r, a.normal);
  double in_plane;
  if (shape == CrackShape::Ellipse) {
    in_plane = DistanceToEllipse(0.5 * length, 0.5 * width, along, up);
  } else {
    const double beyond_length = std::max(std::abs(along) - 0.5 * length, 0.0);
    const double beyond_width = std::max(std::abs(up) - 0.5 * width, 0.0);
    in_plane = std::hypot(beyond_length, beyond_width);
  }
  return std::hypot(in_plane, normal);
}

double crack_distance(const Crack& a, const Crack& b) {
  const auto a0 = a.end(0), a1 = a.end(1), b0 = b.end(0), b1 = b.end(1);
  const double o1 = orient(a0, a1, b0), o2 = orient(a0, a1, b1), o3 = orient(b0, b1, a0), o4 = orient(b0, b1, a1);
  if (((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 * o2 != 0 && o3 * o4 != 0) return 0.0;
  auto point_segment = [](const std::array<double, 2>& p, const std::array<double, 2>& s0,
                          const std::array<double, 2>& s1) {
    const double dx = s1[0] - s0[0], dy = s1[1] - s0[1];
    const double t = std::clamp(((p[0] - s0[0]) * dx + (p[1] - s0[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return std::hypot(p[0] - s0[0] - t * dx, p[1] - s0[1] - t * dy);
  };
  return std::min({point_segment(a0, b0, b1), point_segment(a1, b0, b1), point_segment(b0, a0, a1),
                   point_segment(b1, a0, a1)});
}


bool SpecimenGeometry::end_on_boundary(const Crack& c, int which) const {
  const auto p = c.end(which);
  const double tol = tolerance(*this);
  return std::abs(p[0]) <= tol || std::abs(p[0] - width) <= tol || std::abs(p[1]) <= tol ||
         std::abs(p[1] - height) <= tol;
}

void SpecimenGeometry::validate() const {
  std::ostringstream msg;
  auto positive = [&](const char* option, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      msg << option << " must be > 0, got " << v;
      reject(msg.str());
    }
  };
  positive("-specimen_width", width);
  positive("-specimen_height", height);
  positive("-mesh_h", h);
  positive("-mesh_h_crack", h_crack);
  positive("-mesh_grading", grading);
  if (h_crack > h) {
    msg << "-mesh_h_crack (" << h_crack << ") must not exceed -mesh_h (" << h << ")";
    reject(msg.str());
  }
  if (!std::isfinite(crack_mirror_width)) {
    msg << "-mesh_crack_mirror must be a half-width in metres (0: none; negative: the default width), got " << crack_mirror_width;
    reject(msg.str());
  }
  const double tol = tolerance(*this);
  for (std::size_t i = 0; i < cracks.size(); ++i) {
    const Crack& c = cracks[i];
    const int id = static_cast<int>(i) + 1;
    if (!(c.length > 0.0) || !std::isfinite(c.length)) {
      msg << "-crack_length: crack " << id << " has length " << c.length << " (must be > 0)";
      reject(msg.str());
    }
    if (c.length < 2.0 * h_crack * (1.0 - 1e-12)) {
      msg << "-crack_length: crack " << id << " (length " << c.length << " m) is degenerate: fewer than 2 elements"
          << " along it at -mesh_h_crack " << h_crack;
      reject(msg.str());
    }
    for (int e = 0; e < 2 && depth <= 0.0; ++e) {  // a 3D box checks where its cracks meet its faces (box_grid)
      const auto p = c.end(e);
      if (p[0] < -tol || p[0] > width + tol || p[1] < -tol || p[1] > height + tol) {
        msg << "-crack_center/-crack_length/-crack_angle: crack " << id << " reaches beyond the specimen (end at ("
            << p[0] << ", " << p[1] << "), specimen [0, " << width << "] x [0, " << height << "])";
        reject(msg.str());
      }
    }
    const auto p0 = c.end(0), p1 = c.end(1);
    const bool along_edge = (std::abs(p0[0] - p1[0]) <= tol && (std::abs(p0[0]) <= tol || std::abs(p0[0] - width) <= tol)) ||
                            (std::abs(p0[1] - p1[1]) <= tol && (std::abs(p0[1]) <= tol || std::abs(p0[1] - height) <= tol));
    if (along_edge) {
      msg << "-crack_center: crack " << id << " lies along an outer edge";
      reject(msg.str());
    }
    for (std::size_t j = 0; j < i && depth <= 0.0; ++j) {  // a 3D box checks its cracks' rectangles (box_grid)
      if (crack_distance(c, cracks[j]) < 0.5 * h_crack) {
        msg << "-crack_center: cracks " << j + 1 << " and " << id << " cross or come closer than half an element ("
            << 0.5 * h_crack << " m)";
        reject(msg.str());
      }
    }
  }
  validate_patch();
}

void SpecimenGeometry::validate_patch() const {
  if (!patch.on) return;
  std::ostringstream msg;
  const Side side = patch.side;
  const bool box = depth > 0.0;
  const char* where = box ? "face" : "edge";
  if (!box && static_cast<int>(side) >= 4) {
    msg << "-source_patch_edge " << to_string(side) << " applies to a 3D box only (-specimen_depth > 0)";
    reject(msg.str());
  }
  const double sizes[2] = {patch.width, patch.width2}, tol = 1e-9 * std::max({width, height, depth});
  for (int k = 0; k < (box ? 2 : 1); ++k)
    if (!(sizes[k] > 0.0) || !std::isfinite(sizes[k])) {
      msg << "-source_patch_width must be > 0, got " << sizes[k];
      reject(msg.str());
    }
  for (int k = 0; k < (box ? 2 : 1); ++k) {
    const auto b = patch.bounds(k);
    const double length = extent(face_axes(side)[k]);
    if (std::isfinite(b[0] + b[1]) && b[0] >= -tol && b[1] <= length + tol) continue;
    msg << "-source_patch_center " << (k == 0 ? patch.center : patch.center2) << " with -source_patch_width " << sizes[k]
        << ": the patch [" << b[0] << ", " << b[1] << "] m leaves the " << to_string(side) << " " << where << " [0, "
        << length << "] m" << (box ? (k == 0 ? " (its first axis)" : " (its second axis)") : "");
    reject(msg.str());
  }
  if (face_kind(side) == EdgeKind::Source) {
    msg << "-source_patch_edge " << to_string(side) << ": -edge_" << to_string(side) << " gives the kind of the rest of"
        << " that " << where << " and cannot be source (free, absorbing, roller, ...)";
    reject(msg.str());
  }
}

std::array<std::array<double, 2>, 2> SpecimenGeometry::patch_ends() const {
  switch (patch.side) {
    case Side::Bottom: return {{{patch.start(), 0.0}, {patch.end(), 0.0}}};
    case Side::Top: return {{{patch.start(), height}, {patch.end(), height}}};
    case Side::Left: return {{{0.0, patch.start()}, {0.0, patch.end()}}};
    case Side::Right: return {{{width, patch.start()}, {width, patch.end()}}};
    default: break;  // front, back: 3D faces
  }
  return {};
}

}  // namespace vibrotherm::mesh

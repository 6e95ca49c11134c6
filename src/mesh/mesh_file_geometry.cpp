// A -mesh_file specimen seen as a generated one, so that its heat mesh can be
// generated and graded to its cracks: an axis-aligned rectangle (every outer
// edge on its bounding box) with straight cracks. Anything else keeps the
// unsplit mesh for heat (or takes -heat_mesh_file).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh {
namespace {

using Point = std::array<double, 2>;

Point vertex(const MeshData& m, int v) { return {m.coords[2 * v], m.coords[2 * v + 1]}; }

/// Outer edges: those of exactly one cell.
std::vector<std::pair<int, int>> outer_edges(const MeshData& m) {
  std::map<std::pair<int, int>, int> count;
  for (int c = 0; c < m.cell_count(); ++c)
    for (int i = 0; i < m.corners; ++i) {
      int a = m.cells[c * m.corners + i], b = m.cells[c * m.corners + (i + 1) % m.corners];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<int, int>> out;
  for (const auto& [edge, n] : count)
    if (n == 1) out.push_back(edge);
  return out;
}

}  // namespace

namespace {

std::string at(Point p) {
  char text[96];
  std::snprintf(text, sizeof(text), "(%.4g, %.4g)", p[0], p[1]);
  return text;
}

}  // namespace

bool rectangle_geometry(const MeshData& m, SpecimenGeometry* g, std::string* why) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (int v = 0; v < m.vertex_count(); ++v) {
    const Point p = vertex(m, v);
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  const std::string outline = "the specimen is not the rectangle [0, W] x [0, H] (origin at its bottom-left corner)";
  *why = outline;
  if (std::abs(x0) > 1e-12 || std::abs(y0) > 1e-12) return false;  // the origin is the bottom-left corner
  const double tol = 1e-9 * std::max(x1, y1);
  double longest = 0.0;
  for (const auto& [a, b] : outer_edges(m)) {
    const Point p = vertex(m, a), q = vertex(m, b);
    const bool on_side = (std::abs(p[0] - q[0]) <= tol && (std::abs(p[0]) <= tol || std::abs(p[0] - x1) <= tol)) ||
                         (std::abs(p[1] - q[1]) <= tol && (std::abs(p[1]) <= tol || std::abs(p[1] - y1) <= tol));
    if (!on_side) return false;
    longest = std::max(longest, std::hypot(q[0] - p[0], q[1] - p[1]));
  }
  g->width = x1;
  g->height = y1;
  g->h = longest;
  g->cracks.clear();
  double crack_edges = 0.0, crack_edge_length = 0.0;
  for (std::size_t c = 0; c < m.crack_names.size(); ++c) {
    std::map<int, int> degree;
    for (const MeshEdge& e : m.crack_edges)
      if (e.tag == static_cast<int>(c)) {
        ++degree[e.v0], ++degree[e.v1];
        crack_edge_length += std::hypot(vertex(m, e.v1)[0] - vertex(m, e.v0)[0], vertex(m, e.v1)[1] - vertex(m, e.v0)[1]);
        crack_edges += 1;
      }
    std::vector<Point> ends;
    for (const auto& [v, d] : degree)
      if (d == 1) ends.push_back(vertex(m, v));
    *why = m.crack_names[c] + " is not one open line";
    if (ends.size() != 2) return false;
    const double dx = ends[1][0] - ends[0][0], dy = ends[1][1] - ends[0][1], L = std::hypot(dx, dy);
    Point farthest = ends[0];  // straight: every vertex on the line through the ends
    double off = 0.0;
    for (const auto& [v, d] : degree) {
      const Point p = vertex(m, v);
      const double distance = std::abs((p[0] - ends[0][0]) * dy - (p[1] - ends[0][1]) * dx) / L;
      if (distance > off) off = distance, farthest = p;
    }
    *why = m.crack_names[c] + " is not straight (it bends at " + at(farthest) + ")";
    if (off > 1e-9 * L) return false;
    g->cracks.push_back({0.5 * (ends[0][0] + ends[1][0]), 0.5 * (ends[0][1] + ends[1][1]), L,
                         std::atan2(dy, dx) * 180.0 / M_PI});
  }
  g->h_crack = crack_edges > 0 ? crack_edge_length / crack_edges : g->h;
  why->clear();
  return true;
}

void keep_sinks_of(const MeshData& file, MeshData* heat) {
  // A heat outer edge is a sink when its midpoint lies on a sink edge of the file.
  const double tol = 1e-9 * std::max(1e-300, std::abs(*std::max_element(file.coords.begin(), file.coords.end())));
  std::vector<MeshEdge> kept;
  for (const MeshEdge& e : heat->sink_edges) {
    const Point p = vertex(*heat, e.v0), q = vertex(*heat, e.v1), mid = {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])};
    for (const MeshEdge& s : file.sink_edges) {
      const Point a = vertex(file, s.v0), b = vertex(file, s.v1);
      const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
      const double t = std::clamp(((mid[0] - a[0]) * dx + (mid[1] - a[1]) * dy) / len2, 0.0, 1.0);
      if (std::hypot(mid[0] - a[0] - t * dx, mid[1] - a[1] - t * dy) <= tol) {
        kept.push_back(e);
        break;
      }
    }
  }
  heat->sink_edges = kept;
  heat->kind_edges.clear();  // mechanical kinds belong to the wave mesh
}

}  // namespace vibrotherm::mesh

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh {

void check_crack_lines(const MeshData& mesh, const std::string& where) {
  for (std::size_t c = 0; c < mesh.crack_names.size(); ++c) {
    std::map<int, int> degree;
    std::size_t edges = 0;
    for (const MeshEdge& e : mesh.crack_edges)
      if (e.tag == static_cast<int>(c)) ++degree[e.v0], ++degree[e.v1], ++edges;
    const std::string name = where + ": " + mesh.crack_names[c];
    if (edges < 2) throw std::invalid_argument(name + " is degenerate: fewer than 2 elements along it");
    int ends = 0;
    for (const auto& [v, d] : degree) {
      if (d > 2) throw std::invalid_argument(name + " branches");
      ends += d == 1;
    }
    if (ends != 2) throw std::invalid_argument(name + " is not one open line (" + std::to_string(ends) + " ends)");
    // One open chain: edges = vertices − 1.
    if (edges + 1 != degree.size()) throw std::invalid_argument(name + " is not one connected line");
  }
}

namespace {

using Point = std::array<double, 2>;

Point vertex(const MeshData& m, int v) { return {m.coords[2 * v], m.coords[2 * v + 1]}; }

double cross(Point o, Point a, Point b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); }

/// Whether segments pq and rs cross at a point inside both (their ends apart).
bool segments_cross(Point p, Point q, Point r, Point s) {
  const double d1 = cross(r, s, p), d2 = cross(r, s, q), d3 = cross(p, q, r), d4 = cross(p, q, s);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

std::string where_at(const std::string& where, const std::string& a, const std::string& b, Point p) {
  std::ostringstream msg;
  msg << where << ": cracks " << a << " and " << b << " cross (or touch) at (" << p[0] << ", " << p[1]
      << "): each crack must be a line of its own, apart from the others (the split needs every crack node on one "
         "crack); mesh them so that they do not meet";
  return msg.str();
}

}  // namespace

void check_cracks_apart(const MeshData& mesh, const std::string& where) {
  std::map<int, int> owner;  // crack vertex -> its crack
  for (const MeshEdge& e : mesh.crack_edges)
    for (int v : {e.v0, e.v1}) {
      const auto [it, added] = owner.emplace(v, e.tag);
      if (!added && it->second != e.tag)
        throw std::invalid_argument(where_at(where, mesh.crack_names[std::min(it->second, e.tag)],
                                             mesh.crack_names[std::max(it->second, e.tag)], vertex(mesh, v)));
    }
  for (std::size_t i = 0; i < mesh.crack_edges.size(); ++i)
    for (std::size_t j = i + 1; j < mesh.crack_edges.size(); ++j) {
      const MeshEdge &a = mesh.crack_edges[i], &b = mesh.crack_edges[j];
      if (a.tag == b.tag) continue;
      const Point p = vertex(mesh, a.v0), q = vertex(mesh, a.v1);
      if (!segments_cross(p, q, vertex(mesh, b.v0), vertex(mesh, b.v1))) continue;
      const double t = cross(vertex(mesh, b.v0), vertex(mesh, b.v1), p) /
                       (cross(vertex(mesh, b.v0), vertex(mesh, b.v1), p) - cross(vertex(mesh, b.v0), vertex(mesh, b.v1), q));
      throw std::invalid_argument(where_at(where, mesh.crack_names[std::min(a.tag, b.tag)],
                                           mesh.crack_names[std::max(a.tag, b.tag)],
                                           {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}));
    }
}

}  // namespace vibrotherm::mesh

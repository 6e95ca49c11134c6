#include "vibrotherm/mesh/crack_mirror.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::mesh {
namespace {

using geometry::Add;
using geometry::Dot;
using geometry::Scale;
using geometry::Sub;
using P = CrackMirror::P;

double Cross(const P& a, const P& b) { return a[0] * b[1] - a[1] * b[0]; }

/// Distance from p to the segment [a, b].
double PointSegment(const P& p, const P& a, const P& b) {
  const P ab = Sub(b, a);
  const double len2 = Dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(Dot(Sub(p, a), ab) / len2, 0.0, 1.0) : 0.0;
  return geometry::Norm(Sub(p, Add(a, Scale(t, ab))));
}

bool SegmentsCross(const P& a, const P& b, const P& c, const P& d) {
  const double d1 = Cross(Sub(b, a), Sub(c, a)), d2 = Cross(Sub(b, a), Sub(d, a));
  const double d3 = Cross(Sub(d, c), Sub(a, c)), d4 = Cross(Sub(d, c), Sub(b, c));
  return d1 * d2 < 0.0 && d3 * d4 < 0.0;
}

/// Whether p lies inside the convex, counter-clockwise polygon `poly` (3 points or more).
bool Inside(const P& p, const std::vector<P>& poly) {
  if (poly.size() < 3) return false;
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (Cross(Sub(poly[(i + 1) % poly.size()], poly[i]), Sub(p, poly[i])) < 0.0) return false;
  return true;
}

/// Distance between convex polygons or segments (given as 2 points): 0 when they meet.
double Distance(const std::vector<P>& a, const std::vector<P>& b) {
  for (const P& p : a)
    if (Inside(p, b)) return 0.0;
  for (const P& p : b)
    if (Inside(p, a)) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) {
      const P &a0 = a[i], &a1 = a[(i + 1) % a.size()], &b0 = b[j], &b1 = b[(j + 1) % b.size()];
      if (SegmentsCross(a0, a1, b0, b1)) return 0.0;
      d = std::min({d, PointSegment(a0, b0, b1), PointSegment(b0, a0, a1)});
    }
  return d;
}

struct Fit {
  const SpecimenGeometry& g;
  double margin, tol;
  /// q at least `margin` inside the specimen; or on the outer edge normal to `axis` (≥ 0), `margin` from its ends.
  bool Ok(const P& q, int axis = -1) const {
    for (int k = 0; k < 2; ++k) {
      const bool on_edge = k == axis && (std::abs(q[k]) <= tol || std::abs(q[k] - g.extent(k)) <= tol);
      if (!on_edge && (q[k] < margin || q[k] > g.extent(k) - margin)) return false;
    }
    return true;
  }
};

/// The band's end at crack end `which` (sign −1 at p0, +1 at p1): how far past the end along
/// the crack's direction (negative: short of it), or nothing if the band cannot end there.
std::optional<double> EndOffset(const SpecimenGeometry& g, const Crack& c, int which, const P& d, const P& n,
                                double w, const Fit& fit) {
  const double sign = which == 0 ? -1.0 : 1.0, step = 0.5 * fit.margin;
  const P p = c.end(which);
  auto corners_fit = [&](double t, int axis) {
    const P e = Add(p, Scale(sign * t, d));
    return fit.Ok(Add(e, Scale(w, n)), axis) && fit.Ok(Add(e, Scale(-w, n)), axis);
  };
  double t = w;  // past a tip by the band's width; short of an inclined edge
  if (g.end_on_boundary(c, which)) {
    const int axis = std::abs(p[0]) <= fit.tol || std::abs(p[0] - g.width) <= fit.tol ? 0 : 1;
    if (std::abs(d[axis]) >= 1.0 - 1e-9 && corners_fit(0.0, axis)) return 0.0;  // the edge is the band's end
    t = -step;
  }
  for (; t > -0.5 * c.length + fit.margin; t -= step)  // shortened (short of the end, if it must) until it fits
    if (corners_fit(t, -1)) return t;
  return std::nullopt;
}

/// The band of half-width w around crack i, if it fits the specimen, stays half-way (and an
/// element) from the other cracks and an element from the bands already planned.
std::optional<CrackMirror> TryBand(const SpecimenGeometry& g, std::size_t i, double w,
                                   const std::vector<CrackMirror>& planned) {
  const Crack& c = g.cracks[i];
  const Fit fit{g, g.h_crack, 1e-9 * std::max(g.width, g.height)};
  CrackMirror band;
  band.crack = static_cast<int>(i);
  band.p0 = c.end(0), band.p1 = c.end(1);
  const P d = geometry::Normalized(Sub(band.p1, band.p0));
  band.normal = {-d[1], d[0]};
  band.width = w;
  const auto t0 = EndOffset(g, c, 0, d, band.normal, w, fit), t1 = EndOffset(g, c, 1, d, band.normal, w, fit);
  if (!t0 || !t1 || c.length + *t0 + *t1 < 2.0 * g.h_crack) return std::nullopt;
  band.e0 = Add(band.p0, Scale(-*t0, d));
  band.e1 = Add(band.p1, Scale(*t1, d));
  for (std::size_t j = 0; j < g.cracks.size(); ++j)  // at most half-way to another crack: room for its band
    if (j != i && Distance(band.outline(), {g.cracks[j].end(0), g.cracks[j].end(1)}) <
                      std::max(g.h_crack, 0.5 * crack_distance(c, g.cracks[j])))
      return std::nullopt;
  for (const CrackMirror& other : planned)
    if (Distance(band.outline(), other.outline()) < g.h_crack) return std::nullopt;
  return band;
}

P Vertex(const MeshData& m, int v) { return {m.coords[2 * v], m.coords[2 * v + 1]}; }

P Centroid(const MeshData& m, int cell) {
  P c = {0.0, 0.0};
  for (int k = 0; k < m.corners; ++k) c = Add(c, Vertex(m, m.cells[m.corners * cell + k]));
  return Scale(1.0 / m.corners, c);
}

/// Drops the vertices no cell uses, renumbering cells and edge lists.
void DropUnusedVertices(MeshData* m) {
  std::vector<int> index(m->vertex_count(), -1);
  for (int v : m->cells) index[v] = 0;
  std::vector<double> coords;
  for (int v = 0; v < m->vertex_count(); ++v)
    if (index[v] == 0) {
      index[v] = static_cast<int>(coords.size() / 2);
      coords.insert(coords.end(), {m->coords[2 * v], m->coords[2 * v + 1]});
    }
  for (int& v : m->cells) v = index[v];
  for (auto* edges : {&m->kind_edges, &m->sink_edges, &m->side_edges, &m->crack_edges})
    for (MeshEdge& e : *edges) {
      if (index[e.v0] < 0 || index[e.v1] < 0) throw std::runtime_error("crack mirror: an edge lost its vertex");
      e.v0 = index[e.v0], e.v1 = index[e.v1];
    }
  m->coords = std::move(coords);
}

}  // namespace

std::array<CrackMirror::P, 2> CrackMirror::upper() const {
  return {Add(e0, Scale(width, normal)), Add(e1, Scale(width, normal))};
}

std::array<CrackMirror::P, 2> CrackMirror::lower() const {
  return {Add(e0, Scale(-width, normal)), Add(e1, Scale(-width, normal))};
}

std::vector<CrackMirror::P> CrackMirror::outline() const {
  const auto up = upper(), down = lower();
  return {down[0], down[1], up[1], up[0]};  // n is the tangent turned +90°: counter-clockwise
}

CrackMirror::P CrackMirror::reflect(const P& p) const {
  return Add(p, Scale(-2.0 * Dot(Sub(p, p0), normal), normal));
}

double DefaultMirrorWidth(const SpecimenGeometry& g) {
  return std::max((g.h - g.h_crack) / g.grading, 4.0 * g.h_crack);
}

CrackMirrorPlan PlanCrackMirror(const SpecimenGeometry& g, double width) {
  CrackMirrorPlan plan;
  if (!(width > 0.0)) return plan;
  for (std::size_t i = 0; i < g.cracks.size(); ++i) {
    std::optional<CrackMirror> band;
    for (double w = width; !band && w >= 2.0 * g.h_crack * (1.0 - 1e-9); w *= 0.75)  // narrowed until it fits
      band = TryBand(g, i, w, plan.bands);
    if (band) plan.bands.push_back(*band);
    else
      plan.why.push_back("crack " + std::to_string(i + 1) +
                         ": no band of two elements or more on each side fits between it and the edges or other cracks");
  }
  return plan;
}

}  // namespace vibrotherm::mesh

namespace vibrotherm::mesh {

void MirrorBandCells(const CrackMirror& band, MeshData* mesh) {
  const auto up = band.upper(), down = band.lower();
  const std::vector<P> upper_side = {band.e0, band.e1, up[1], up[0]}, lower_side = {band.e0, down[0], down[1], band.e1};
  const int k = mesh->corners, cells = mesh->cell_count();
  std::vector<int> side(cells, 0);  // +1 upper, −1 lower, 0 outside
  for (int c = 0; c < cells; ++c) {
    const P x = Centroid(*mesh, c);
    side[c] = Inside(x, upper_side) ? 1 : Inside(x, lower_side) ? -1 : 0;
  }
  // The vertices the lower side shares with the rest of the mesh stay: its outline and the line.
  std::vector<bool> kept(mesh->vertex_count(), false), lower(mesh->vertex_count(), false);
  for (int c = 0; c < cells; ++c)
    for (int j = 0; j < k; ++j) (side[c] >= 0 ? kept : lower)[mesh->cells[k * c + j]] = true;
  for (const auto* edges : {&mesh->kind_edges, &mesh->sink_edges, &mesh->side_edges, &mesh->crack_edges})
    for (const MeshEdge& e : *edges) kept[e.v0] = kept[e.v1] = true;  // an outer edge where the band reaches one
  std::vector<int> outline;
  for (int v = 0; v < mesh->vertex_count(); ++v)
    if (kept[v] && lower[v]) outline.push_back(v);
  const double tol = 1e-9 * band.width;
  std::vector<int> image(mesh->vertex_count(), -1);
  auto reflected = [&](int v) {
    if (image[v] >= 0) return image[v];
    const P x = Vertex(*mesh, v);
    if (std::abs(Dot(Sub(x, band.p0), band.normal)) < tol) return image[v] = v;  // on the line
    const P y = band.reflect(x);
    for (int w : outline)
      if (geometry::Norm(Sub(Vertex(*mesh, w), y)) < tol) return image[v] = w;
    image[v] = mesh->vertex_count();
    mesh->coords.insert(mesh->coords.end(), {y[0], y[1]});
    return image[v];
  };
  std::vector<int> result;
  for (int c = 0; c < cells; ++c)
    if (side[c] >= 0) result.insert(result.end(), mesh->cells.begin() + k * c, mesh->cells.begin() + k * (c + 1));
  for (int c = 0; c < cells; ++c) {
    if (side[c] != 1) continue;
    for (int j = k - 1; j >= 0; --j) result.push_back(reflected(mesh->cells[k * c + j]));  // reversed: counter-clockwise
  }
  for (int w : outline)  // every vertex the lower side shares must be the image of one on the upper side
    if (std::find(image.begin(), image.end(), w) == image.end())
      throw std::runtime_error("crack mirror: the mesh of a band's lower outline is not the upper one's reflected");
  mesh->cells = std::move(result);
  DropUnusedVertices(mesh);
}

}  // namespace vibrotherm::mesh

#include "vibrotherm/interface/contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibrotherm::interface {
namespace {

double Length(const CrackFacetGeometry& f) { return geometry::Norm(geometry::Sub(f.p1, f.p0)); }

/// Lumped ∫φ ds of a vertex node per unit facet length: P1 1/2, P2 (Simpson) 1/6.
double EndWeight(int degree) { return degree == 2 ? 1.0 / 6.0 : 0.5; }

}  // namespace

ContactGeometry::ContactGeometry(const std::vector<CrackFacetGeometry>& facets, int degree) : degree_(degree) {
  // A crack's ends are the facet end points used once; its direction runs from
  // the end on its first facet (lowest id) to the end on its last.
  struct Ends {
    long first = std::numeric_limits<long>::max(), last = -1;
    const CrackFacetGeometry *first_facet = nullptr, *last_facet = nullptr;
    std::map<std::pair<double, double>, int> uses;
  };
  std::map<int, Ends> ends;
  for (const CrackFacetGeometry& f : facets) {
    frames_[f.crack].length += Length(f);
    Ends& e = ends[f.crack];
    if (f.id < e.first) e.first = f.id, e.first_facet = &f;
    if (f.id > e.last) e.last = f.id, e.last_facet = &f;
    ++e.uses[{f.p0[0], f.p0[1]}];
    ++e.uses[{f.p1[0], f.p1[1]}];
  }
  for (auto& [crack, fr] : frames_) {
    Ends& e = ends[crack];
    auto free_end = [&e](const CrackFacetGeometry* f) {
      return e.uses[{f->p0[0], f->p0[1]}] == 1 ? f->p0 : f->p1;
    };
    const Vec2 a = free_end(e.first_facet), b = free_end(e.last_facet);
    const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (L > 0) fr.direction = {(b[0] - a[0]) / L, (b[1] - a[1]) / L};
    fr.centre = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
  }
  const double end_weight = EndWeight(degree);
  for (const CrackFacetGeometry& f : facets) {
    const Vec2 s = tangent(f);
    const double L = Length(f);
    for (const Vec2& p : {f.p0, f.p1}) {
      NodeSum& node = nodes_[{p[0], p[1]}];
      node.weight += end_weight * L;
      node.sx += end_weight * L * s[0];
      node.sy += end_weight * L * s[1];
    }
  }
}

Vec2 ContactGeometry::tangent(const CrackFacetGeometry& f) const {
  const CrackFrame& fr = frames_.at(f.crack);
  const Vec2 s = geometry::Normalized(geometry::Sub(f.p1, f.p0));
  return geometry::Dot(s, fr.direction) < 0 ? geometry::Scale(-1.0, s) : s;
}

NodeGeometry ContactGeometry::vertex(const Vec2& p) const {
  const NodeSum& node = nodes_.at({p[0], p[1]});
  const double norm = std::hypot(node.sx, node.sy);
  return {node.weight, {node.sx / norm, node.sy / norm}};
}

NodeGeometry ContactGeometry::middle(const CrackFacetGeometry& f) const { return {4.0 / 6.0 * Length(f), tangent(f)}; }

double ContactGeometry::xi(int crack, const Vec2& p) const {
  const CrackFrame& fr = frames_.at(crack);
  return std::clamp(0.5 + ((p[0] - fr.centre[0]) * fr.direction[0] + (p[1] - fr.centre[1]) * fr.direction[1]) / fr.length,
                    0.0, 1.0);
}

}  // namespace vibrotherm::interface

#include "vibrotherm/interface/contact_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::interface {
namespace {

/// Lumped ∫φ ds of a vertex node per unit facet length: P1 1/2, P2 (Simpson) 1/6.
double EndWeight(int degree) { return degree == 2 ? 1.0 / 6.0 : 0.5; }

}  // namespace

ContactGeometry::ContactGeometry(const std::vector<CrackFacetGeometry>& facets, int degree)
    : degree_(degree), frames_(geometry::CrackChords(facets)) {
  const double end_weight = EndWeight(degree);
  for (const CrackFacetGeometry& f : facets) {
    const Vec2 s = tangent(f);
    const double L = geometry::Measure(f);
    for (const Vec2& p : {f.p0, f.p1}) {
      NodeSum& node = nodes_[{p[0], p[1]}];
      node.weight += end_weight * L;
      node.sx += end_weight * L * s[0];
      node.sy += end_weight * L * s[1];
    }
  }
}

Vec2 ContactGeometry::tangent(const CrackFacetGeometry& f) const {
  return geometry::TangentAlong(f, frames_.at(f.crack));
}

NodeGeometry ContactGeometry::vertex(const Vec2& p) const {
  const NodeSum& node = nodes_.at({p[0], p[1]});
  const double norm = std::hypot(node.sx, node.sy);
  return {node.weight, {node.sx / norm, node.sy / norm}};
}

NodeGeometry ContactGeometry::middle(const CrackFacetGeometry& f) const {
  return {4.0 / 6.0 * geometry::Measure(f), tangent(f)};
}

double ContactGeometry::xi(int crack, const Vec2& p) const {
  const CrackFrame& fr = frames_.at(crack);
  return std::clamp(0.5 + ((p[0] - fr.centre[0]) * fr.direction[0] + (p[1] - fr.centre[1]) * fr.direction[1]) /
                              fr.length,
                    0.0, 1.0);
}

}  // namespace vibrotherm::interface

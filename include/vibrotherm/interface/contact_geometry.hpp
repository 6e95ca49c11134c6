// Contact-cell geometry from the crack facets, as a pure function of them (no
// PETSc): unit tests check it alone. Conventions (PHYSICS.md §3.1): the tangent
// s of a crack runs from its first facet (lowest crack_face id, the end with
// the smaller x) to its last; n = s rotated by +90° points from the − face into
// the + body. A vertex node's tributary length is ∫φ ds over its facets (degree
// 1: half of each; degree 2, Simpson: a sixth of each), a mid-side node's 4/6 of
// its facet; the weights of a crack sum to its length.
#pragma once

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "vibrotherm/geometry/crack_chord.hpp"
#include "vibrotherm/geometry/crack_facet.hpp"
#include "vibrotherm/geometry/frame.hpp"

namespace vibrotherm::interface {

using geometry::Vec2;

/// A crack facet as every rank knows it.
using CrackFacetGeometry = geometry::CrackFacet;

/// A crack's direction (unit, first facet → last), centre and length.
using CrackFrame = geometry::CrackChord;

/// A contact node's tributary length [m] and unit tangent.
struct NodeGeometry {
  double weight = 0.0;
  Vec2 tangent{1.0, 0.0};
};

class ContactGeometry {
 public:
  /// All facets of all cracks (the same list on every rank); degree 1 or 2.
  ContactGeometry(const std::vector<CrackFacetGeometry>& facets, int degree);

  const CrackFrame& frame(int crack) const { return frames_.at(crack); }
  /// Unit tangent of a facet, along its crack's direction.
  Vec2 tangent(const CrackFacetGeometry& facet) const;
  /// The vertex node at p (a facet end point).
  NodeGeometry vertex(const Vec2& p) const;
  /// The mid-side node of a facet (degree 2).
  NodeGeometry middle(const CrackFacetGeometry& facet) const;
  /// ξ of p: 0.5 + (p − centre)·direction / length, in [0, 1].
  double xi(int crack, const Vec2& p) const;
  static Vec2 normal(const Vec2& s) { return geometry::FrameFromTangent(s).normal; }
  int degree() const { return degree_; }

 private:
  int degree_;
  std::map<int, CrackFrame> frames_;
  struct NodeSum {
    double weight = 0.0, sx = 0.0, sy = 0.0;
  };
  std::map<std::pair<double, double>, NodeSum> nodes_;  ///< by vertex coordinates (both faces share them)
};

}  // namespace vibrotherm::interface

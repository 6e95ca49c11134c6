// A 2D crack's chord, from its facets alone (PETSc-free): the direction every
// convention along a 2D crack starts from (PHYSICS.md §3.1). The chord runs from
// the free end of the crack's first facet (lowest crack_face id) to the free end
// of its last; a facet's tangent is turned to run along it, and n, the tangent
// turned by +90°, points from the − face into the + body. The crack split labels
// the + faces by it (mesh/plex/crack_split), the contact cells take their
// tangents and ξ from it (interface/contact_geometry).
#pragma once

#include <map>
#include <vector>

#include "vibrotherm/geometry/crack_facet.hpp"

namespace vibrotherm::geometry {

struct CrackChord {
  Vec2 direction{1.0, 0.0}, centre{};  ///< unit, first facet → last; midpoint of the free ends
  double length = 0.0;                 ///< the facets' total length (not the chord's)
};

/// Per crack (0-based), from all its facets.
std::map<int, CrackChord> CrackChords(const std::vector<CrackFacet>& facets);

/// The unit tangent p0 → p1 of a facet, turned to run along its crack's chord.
Vec2 TangentAlong(const CrackFacet& facet, const CrackChord& chord);

}  // namespace vibrotherm::geometry

// A crack facet as every rank knows it once the crack surface has gathered it:
// its crack_face id, its crack and its vertices (the mesh's cone order). 2D: a
// segment; a 3D facet will carry its polygon's vertices.
#pragma once

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::geometry {

struct CrackFacet {
  long id = 0;    ///< crack_face id: numbers the facets along each crack, the same on every mesh
  int crack = 0;  ///< 0-based
  Vec2 p0{}, p1{};
};

/// The facet's measure (2D: its length), what it adds to its crack's area.
inline double Measure(const CrackFacet& f) { return Norm(Sub(f.p1, f.p0)); }

}  // namespace vibrotherm::geometry

#include "vibrotherm/geometry/crack_chord.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace vibrotherm::geometry {

std::map<int, CrackChord> CrackChords(const std::vector<CrackFacet>& facets) {
  struct Ends {
    long first = std::numeric_limits<long>::max(), last = -1;
    const CrackFacet *first_facet = nullptr, *last_facet = nullptr;
    std::map<std::pair<double, double>, int> uses;  // an end point is used by one facet only
  };
  std::map<int, CrackChord> chords;
  std::map<int, Ends> ends;
  for (const CrackFacet& f : facets) {
    chords[f.crack].length += Measure(f);
    Ends& e = ends[f.crack];
    if (f.id < e.first) e.first = f.id, e.first_facet = &f;
    if (f.id > e.last) e.last = f.id, e.last_facet = &f;
    ++e.uses[{f.p0[0], f.p0[1]}];
    ++e.uses[{f.p1[0], f.p1[1]}];
  }
  for (auto& [crack, chord] : chords) {
    Ends& e = ends[crack];
    auto free_end = [&e](const CrackFacet* f) { return e.uses[{f->p0[0], f->p0[1]}] == 1 ? f->p0 : f->p1; };
    const Vec2 a = free_end(e.first_facet), b = free_end(e.last_facet);
    const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (L > 0) chord.direction = {(b[0] - a[0]) / L, (b[1] - a[1]) / L};
    chord.centre = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
  }
  return chords;
}

Vec2 TangentAlong(const CrackFacet& facet, const CrackChord& chord) {
  const Vec2 s = Normalized(Sub(facet.p1, facet.p0));
  return Dot(s, chord.direction) < 0 ? Scale(-1.0, s) : s;
}

}  // namespace vibrotherm::geometry

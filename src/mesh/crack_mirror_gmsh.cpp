#include "crack_mirror_gmsh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vibrotherm::mesh::crack_mirror_gmsh {
namespace {

using P = CrackMirror::P;

double Distance(const P& a, const P& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

/// Position of p along the crack's line, from p0 [m].
double Along(const CrackMirror& band, const P& p) {
  return (p[0] - band.p0[0]) * band.normal[1] - (p[1] - band.p0[1]) * band.normal[0];
}

/// Distance of p from the crack's line, signed along n [m].
double Across(const CrackMirror& band, const P& p) {
  return (p[0] - band.p0[0]) * band.normal[0] + (p[1] - band.p0[1]) * band.normal[1];
}

P Offset(const CrackMirror& band, const P& p, double distance) {
  return {p[0] + distance * band.normal[0], p[1] + distance * band.normal[1]};
}

int AddPoint(const P& p) { return gmsh::model::occ::addPoint(p[0], p[1], 0.0); }

/// The curves bounding a surface, with their end points.
struct BoundaryCurve {
  int tag;
  P a, b;
};
std::vector<BoundaryCurve> Boundary(int surface) {
  gmsh_support::DimTags curves;
  gmsh::model::getBoundary({{2, surface}}, curves, false, false, false);
  std::vector<BoundaryCurve> out;
  for (const auto& [dim, signed_tag] : curves) {
    const auto [a, b] = gmsh_support::curve_end_points(std::abs(signed_tag));
    out.push_back({std::abs(signed_tag), a, b});
  }
  return out;
}

/// The lower side's curves paired with their mirror images on the upper side (the line's own skipped).
void PairCurves(const CrackMirror& band, int upper, int lower, std::vector<int>* slaves, std::vector<int>* masters) {
  const double tol = 1e-6 * band.width;
  const std::vector<BoundaryCurve> images = Boundary(upper);
  for (const BoundaryCurve& c : Boundary(lower)) {
    if (std::abs(Across(band, c.a)) < tol && std::abs(Across(band, c.b)) < tol) continue;
    const P a = band.reflect(c.a), b = band.reflect(c.b);
    const auto image = std::find_if(images.begin(), images.end(), [&](const BoundaryCurve& m) {
      return (Distance(m.a, a) < tol && Distance(m.b, b) < tol) || (Distance(m.a, b) < tol && Distance(m.b, a) < tol);
    });
    if (image == images.end()) throw std::runtime_error("gmsh: a crack's mirror band lost the image of a curve");
    slaves->push_back(c.tag);
    masters->push_back(image->tag);
  }
}

}  // namespace

BandShapes AddBand(const CrackMirror& band) {
  namespace occ = gmsh::model::occ;
  const double tol = 1e-6 * band.width;
  // The points along the line in order: the band's ends and the crack's (equal ones once).
  std::vector<P> along = {band.e0, band.p0, band.p1, band.e1};
  std::sort(along.begin(), along.end(), [&](const P& x, const P& y) { return Along(band, x) < Along(band, y); });
  along.erase(std::unique(along.begin(), along.end(), [&](const P& x, const P& y) { return Distance(x, y) < tol; }),
              along.end());
  std::vector<int> points;
  for (const P& p : along) points.push_back(AddPoint(p));
  const double s0 = Along(band, band.e0), s1 = Along(band, band.e1), crack_end = Along(band, band.p1);
  BandShapes shapes;
  std::vector<int> middle;  // the pieces between the band's ends: shared by both sides
  int e0 = -1, e1 = -1;
  for (std::size_t k = 0; k < along.size(); ++k) {
    if (std::abs(Along(band, along[k]) - s0) < tol) e0 = points[k];
    if (std::abs(Along(band, along[k]) - s1) < tol) e1 = points[k];
  }
  for (std::size_t k = 0; k + 1 < along.size(); ++k) {
    const int line = occ::addLine(points[k], points[k + 1]);
    const double mid = 0.5 * (Along(band, along[k]) + Along(band, along[k + 1]));
    if (mid > s0 && mid < s1) middle.push_back(line);
    if (mid > 0.0 && mid < crack_end) shapes.crack_lines.push_back(line);
  }
  auto half = [&](double sign) {
    const int f0 = AddPoint(Offset(band, band.e0, sign * band.width)), f1 = AddPoint(Offset(band, band.e1, sign * band.width));
    std::vector<int> loop = middle;
    for (int c : {occ::addLine(e1, f1), occ::addLine(f1, f0), occ::addLine(f0, e0)}) loop.push_back(c);
    return occ::addPlaneSurface({occ::addCurveLoop(loop)});
  };
  shapes.upper = half(1.0);
  shapes.lower = half(-1.0);
  return shapes;
}

void MirrorOutline(const CrackMirror& band, int upper, int lower) {
  std::vector<int> slaves, masters;
  PairCurves(band, upper, lower, &slaves, &masters);
  // x' = R x + t with R = I − 2 n nᵀ, t = 2 (n·p0) n: the reflection across the crack's line (4 × 4, row major).
  const P& n = band.normal;
  const double c = 2.0 * (n[0] * band.p0[0] + n[1] * band.p0[1]);
  const std::vector<double> reflection = {1.0 - 2.0 * n[0] * n[0], -2.0 * n[0] * n[1], 0.0, c * n[0],
                                          -2.0 * n[1] * n[0], 1.0 - 2.0 * n[1] * n[1], 0.0, c * n[1],
                                          0.0, 0.0, 1.0, 0.0,
                                          0.0, 0.0, 0.0, 1.0};
  gmsh::model::mesh::setPeriodic(1, slaves, masters, reflection);
}

}  // namespace vibrotherm::mesh::crack_mirror_gmsh

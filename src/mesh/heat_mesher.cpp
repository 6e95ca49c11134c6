// Generated specimen → heat mesh (heat_mesh.hpp): a graded structured band of
// quads around every crack, an unstructured quad mesh elsewhere (gmsh, OCC).
//
// A band in the crack's frame (σ along the crack from end 0, ν = normal
// offset) is a grid of column boundaries σ_k × rows ν ∈ {−δ, 0, +δ}: columns
// [−e, 0] (past a buried end), [0, L] (the crack), [L, L + e]; below and above
// the crack line one transfinite quad per column. At an end on the outer edge
// the column boundary is that edge itself (σ depends on ν there).
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "gmsh_support.hpp"
#include "vibrotherm/mesh/heat_mesh.hpp"

namespace vibrotherm::mesh {

int HeatMeshSizes::layers() const {
  // Even: the full-quad fallback meshes half the layers with growth² and splits
  // each in two, which restores every layer exactly only for an even count.
  if (h_crack >= h_along) return 2;
  const double n = growth <= 1.0 ? std::ceil(h_along / h_crack) : std::ceil(std::log(h_along / h_crack) / std::log(growth));
  return 2 * std::max(1, static_cast<int>(std::ceil(n / 2.0)));
}

double HeatMeshSizes::band_half_width(int n) const {
  return growth == 1.0 ? n * h_crack : h_crack * (std::pow(growth, n) - 1.0) / (growth - 1.0);
}

void HeatMeshSizes::validate() const {
  auto positive = [](const char* option, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      std::ostringstream msg;
      msg << option << " must be > 0, got " << v;
      throw std::invalid_argument(msg.str());
    }
  };
  positive("-heat_mesh_h_crack", h_crack);
  positive("-heat_mesh_h_along", h_along);
  positive("-heat_mesh_h", h);
  positive("-heat_mesh_grading", grading);
  if (!(growth >= 1.0 && growth <= 2.0)) {
    std::ostringstream msg;
    msg << "-heat_mesh_growth must be in [1, 2], got " << growth;
    throw std::invalid_argument(msg.str());
  }
  if (h_crack > h_along || h_along > h) {
    std::ostringstream msg;
    msg << "heat mesh sizes must satisfy -heat_mesh_h_crack (" << h_crack << ") <= -heat_mesh_h_along (" << h_along
        << ") <= -heat_mesh_h (" << h << ")";
    throw std::invalid_argument(msg.str());
  }
}

namespace {

using namespace gmsh_support;
using Point = std::array<double, 2>;

/// One crack's band: frame, layers and column boundaries.
struct Band {
  int crack = 0;
  Point origin{}, s{}, n{};  ///< end 0, unit tangent, unit normal (s rotated +90°)
  double length = 0, delta = 0;
  int layers = 0;
  bool on_edge[2] = {false, false};
  std::vector<double> sigma;  ///< σ of the column boundaries (buried ends: fixed)
  std::vector<int> along;     ///< elements along each column
  int crack_column = 0;

  Point at(double sig, double nu) const {
    return {origin[0] + sig * s[0] + nu * n[0], origin[1] + sig * s[1] + nu * n[1]};
  }
  double sigma_of(const Point& p) const { return (p[0] - origin[0]) * s[0] + (p[1] - origin[1]) * s[1]; }
  double nu_of(const Point& p) const { return (p[0] - origin[0]) * n[0] + (p[1] - origin[1]) * n[1]; }
};

/// Distance from a crack's end points to an axis-parallel side line of the rectangle.
double side_distance(const Point& p, const SpecimenGeometry& g, Side side) {
  switch (side) {
    case Side::Bottom: return p[1];
    case Side::Right: return g.width - p[0];
    case Side::Top: return g.height - p[1];
    case Side::Left: return p[0];
    default: break;  // front, back: 3D faces
  }
  return 0.0;
}

/// The side an end lies on (only called for ends on the boundary).
Side side_of(const Point& p, const SpecimenGeometry& g) {
  const double tol = 1e-9 * std::max(g.width, g.height);
  for (Side side : {Side::Bottom, Side::Right, Side::Top, Side::Left})
    if (std::abs(side_distance(p, g, side)) <= tol) return side;
  throw std::logic_error("crack end is not on an outer edge");
}

/// Largest band half-width crack i may have: its band must stay clear of the
/// other bands and of the outer edges it does not end on.
double clearance(const SpecimenGeometry& g, std::size_t i) {
  const Crack& c = g.cracks[i];
  double d_cracks = INFINITY, d_edges = INFINITY;
  for (std::size_t j = 0; j < g.cracks.size(); ++j)
    if (j != i) d_cracks = std::min(d_cracks, crack_distance(c, g.cracks[j]));
  for (Side side : {Side::Bottom, Side::Right, Side::Top, Side::Left}) {
    bool ends_here = false;
    double d = INFINITY;
    for (int k = 0; k < 2; ++k) {
      const Point p = c.end(k);
      ends_here = ends_here || (g.end_on_boundary(c, k) && side_of(p, g) == side);
      d = std::min(d, side_distance(p, g, side));
    }
    if (!ends_here) d_edges = std::min(d_edges, d);
  }
  return std::min(0.45 * d_cracks, 0.6 * d_edges);
}

Band plan_band(const SpecimenGeometry& g, const HeatMeshSizes& sizes, std::size_t i) {
  const Crack& c = g.cracks[i];
  Band b;
  b.crack = static_cast<int>(i);
  b.origin = c.end(0);
  const Point e1 = c.end(1);
  b.length = c.length;
  b.s = {(e1[0] - b.origin[0]) / c.length, (e1[1] - b.origin[1]) / c.length};
  b.n = {-b.s[1], b.s[0]};
  b.layers = sizes.layers();
  const double room = clearance(g, i);
  while (b.layers > 2 && sizes.band_half_width(b.layers) > room) b.layers -= 2;
  b.delta = sizes.band_half_width(b.layers);
  if (b.delta > room) {
    std::ostringstream msg;
    msg << "heat mesh: crack " << i + 1 << " is too close to another crack or an outer edge for one layer of "
        << "-heat_mesh_h_crack " << sizes.h_crack << " m (room " << room << " m)";
    throw std::invalid_argument(msg.str());
  }
  for (int k = 0; k < 2; ++k) b.on_edge[k] = g.end_on_boundary(c, k);
  const double e = b.delta;  // a buried end: the band goes on by its half-width
  const int n_ext = std::max(1, static_cast<int>(std::ceil(e / sizes.h_along - 1e-9)));
  if (!b.on_edge[0]) b.sigma.push_back(-e), b.along.push_back(n_ext);
  b.crack_column = static_cast<int>(b.along.size());
  b.sigma.push_back(0.0);
  b.along.push_back(std::max(2, static_cast<int>(std::ceil(c.length / sizes.h_along - 1e-9))));
  b.sigma.push_back(c.length);
  if (!b.on_edge[1]) b.sigma.push_back(c.length + e), b.along.push_back(n_ext);
  return b;
}

/// σ where the row ν meets the column boundary k (an outer edge at an end on it).
double boundary_sigma(const Band& b, const SpecimenGeometry& g, std::size_t k, double nu) {
  const bool first = k == 0, last = k + 1 == b.sigma.size();
  const int end = first ? 0 : 1;
  if (!((first || last) && b.on_edge[end]) || nu == 0.0) return b.sigma[k];
  const Point p = b.at(b.sigma[k], 0.0);
  const Side side = side_of(p, g);
  const bool vertical = side == Side::Left || side == Side::Right;
  const double sd = vertical ? b.s[0] : b.s[1], nd = vertical ? b.n[0] : b.n[1];
  // Along the edge line: (p + ν n + t s)·axis = p·axis ⇒ t = −ν nd / sd.
  const double t = -nu * nd / sd;
  const Point q = b.at(b.sigma[k] + t, nu);
  const double span = vertical ? g.height : g.width, along = vertical ? q[1] : q[0];
  if (std::abs(t) > 0.5 * b.length || along < 0.0 || along > span) {
    std::ostringstream msg;
    msg << "heat mesh: crack " << b.crack + 1 << " meets the outer edge too obliquely or too close to a corner "
        << "for its heat band (half-width " << b.delta << " m); use -heat_mesh wave";
    throw std::invalid_argument(msg.str());
  }
  return b.sigma[k] + t;
}

/// Builds the band's transfinite quads (OCC) and returns their surface tags.
std::vector<int> build_band(const Band& b, const SpecimenGeometry& g) {
  const double rows[3] = {-b.delta, 0.0, b.delta};
  std::vector<std::array<int, 3>> points(b.sigma.size());
  for (std::size_t k = 0; k < b.sigma.size(); ++k)
    for (int r = 0; r < 3; ++r) {
      const Point p = b.at(boundary_sigma(b, g, k, rows[r]), rows[r]);
      points[k][r] = gmsh::model::occ::addPoint(p[0], p[1], 0.0);
    }
  std::vector<int> surfaces;
  for (std::size_t j = 0; j + 1 < b.sigma.size(); ++j)
    for (int side : {0, 2}) {  // below (row 0) and above (row 2) the crack line (row 1)
      const int a = points[j][1], bb = points[j + 1][1], c = points[j + 1][side], d = points[j][side];
      const std::vector<int> loop = {gmsh::model::occ::addLine(a, bb), gmsh::model::occ::addLine(bb, c),
                                     gmsh::model::occ::addLine(c, d), gmsh::model::occ::addLine(d, a)};
      surfaces.push_back(gmsh::model::occ::addPlaneSurface({gmsh::model::occ::addCurveLoop(loop)}));
    }
  return surfaces;
}

/// Node distribution of one boundary curve of a band quad; records crack curves.
void constrain_curve(const Band& b, const HeatMeshSizes& sizes, int curve, bool coarse, std::vector<int>* crack_curves) {
  const auto [p, q] = curve_end_points(curve);
  const double nu_p = b.nu_of(p), nu_q = b.nu_of(q), sig = 0.5 * (b.sigma_of(p) + b.sigma_of(q));
  const double tol = 1e-6 * b.delta;
  // coarse: half as many nodes, the mesh is subdivided afterwards (full-quad fallback)
  if (std::abs(nu_p - nu_q) > 0.5 * b.delta) {  // across the band: graded layers from the crack line
    const bool far_end = sig < -0.5 * b.delta || sig > b.length + 0.5 * b.delta;
    const int layers = coarse ? b.layers / 2 : b.layers;
    const double ratio = far_end ? 1.0 : (coarse ? sizes.growth * sizes.growth : sizes.growth);
    const bool starts_at_crack = std::abs(nu_p) < std::abs(nu_q);
    gmsh::model::mesh::setTransfiniteCurve(curve, layers + 1, "Progression", starts_at_crack ? ratio : 1.0 / ratio);
    return;
  }
  std::size_t column = 0;
  while (column + 1 < b.along.size() && sig > b.sigma[column + 1]) ++column;
  const int n = coarse ? (b.along[column] + 1) / 2 : b.along[column];
  gmsh::model::mesh::setTransfiniteCurve(curve, n + 1);
  if (static_cast<int>(column) == b.crack_column && std::abs(nu_p) < tol && std::abs(nu_q) < tol)
    crack_curves->push_back(curve);
}

/// Size away from the bands: h_along at the band edges, growing by `grading` to h.
void set_outer_size(HeatMeshSizes sizes, const std::vector<double>& band_edges, bool coarse) {
  if (coarse) sizes.h *= 2.0, sizes.h_along *= 2.0;  // subdivided afterwards
  set_graded_size(band_edges, {sizes.h_along, sizes.h, 0.0, (sizes.h - sizes.h_along) / sizes.grading, 200});
}

/// Transfinite constraints on every band quad; returns the crack curves per crack.
std::vector<std::vector<int>> constrain_bands(const std::vector<Band>& bands, const std::vector<DimTags>& band_surfaces,
                                              const HeatMeshSizes& sizes, bool coarse) {
  std::vector<std::vector<int>> crack_curves(bands.size());
  for (std::size_t i = 0; i < bands.size(); ++i)
    for (const auto& [dim, surface] : band_surfaces[i]) {
      DimTags curves;
      gmsh::model::getBoundary({{2, surface}}, curves, false, false, false);
      if (curves.size() != 4) throw std::runtime_error("heat mesh: a band quad of crack " + std::to_string(i + 1) +
                                                       " has " + std::to_string(curves.size()) + " sides");
      for (const auto& [cdim, curve] : curves) constrain_curve(bands[i], sizes, std::abs(curve), coarse, &crack_curves[i]);
      gmsh::model::mesh::setTransfiniteSurface(surface);
      gmsh::model::mesh::setRecombine(2, surface);
    }
  for (auto& curves : crack_curves) {
    std::sort(curves.begin(), curves.end());
    curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  }
  return crack_curves;
}

/// Curves of the bands that face the unstructured region (for its size field).
std::vector<double> band_edges(const std::vector<DimTags>& band_surfaces) {
  DimTags all;
  for (const DimTags& s : band_surfaces) all.insert(all.end(), s.begin(), s.end());
  DimTags outline;
  gmsh::model::getBoundary(all, outline, true, false, false);  // combined: the bands' outer outline
  std::vector<double> tags;
  for (const auto& [dim, tag] : outline) tags.push_back(std::abs(tag));
  return tags;
}

}  // namespace

MeshData generate_heat_mesh(const SpecimenGeometry& g, const HeatMeshSizes& sizes) {
  sizes.validate();
  GmshSession session;
  gmsh::model::add("heat");
  const int rectangle = gmsh::model::occ::addRectangle(0, 0, 0, g.width, g.height);
  std::vector<Band> bands;
  DimTags tools;
  std::vector<std::size_t> first_tool;
  for (std::size_t i = 0; i < g.cracks.size(); ++i) {
    bands.push_back(plan_band(g, sizes, i));
    first_tool.push_back(tools.size());
    for (int s : build_band(bands.back(), g)) tools.push_back({2, s});
  }
  DimTags out;
  std::vector<DimTags> produced(1 + tools.size());
  if (!tools.empty()) gmsh::model::occ::fragment({{2, rectangle}}, tools, out, produced);
  gmsh::model::occ::synchronize();
  std::vector<DimTags> band_surfaces(bands.size());
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const std::size_t end = i + 1 < bands.size() ? first_tool[i + 1] : tools.size();
    for (std::size_t t = first_tool[i]; t < end; ++t)
      for (const auto& dt : produced[1 + t]) band_surfaces[i].push_back(dt);
  }
  const std::vector<double> outline = band_edges(band_surfaces);
  set_outer_size(sizes, outline, false);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // frontal-Delaunay (8 crashes with embedded lines)
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);  // blossom
  auto crack_curves = constrain_bands(bands, band_surfaces, sizes, false);
  gmsh::model::mesh::generate(2);
  if (has_triangles()) {
    // Recombination left triangles: mesh with half the nodes and subdivide every
    // cell into quads (the graded layers split in two: thickness ≈ kept).
    gmsh::model::mesh::clear();
    set_outer_size(sizes, outline, true);
    crack_curves = constrain_bands(bands, band_surfaces, sizes, true);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
    gmsh::model::mesh::generate(2);
  }

  return collect_rectangle_mesh(g, crack_curves, "heat mesh");
}

}  // namespace vibrotherm::mesh

#include "vibrotherm/mesh/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vibrotherm::mesh {
namespace {

/// Throws std::invalid_argument with the parts streamed one after the other.
template <class... Parts>
[[noreturn]] void reject(const Parts&... parts) {
  std::ostringstream msg;
  (msg << ... << parts);
  throw std::invalid_argument(msg.str());
}

/// The steps from a breakpoint over `distance`: sizes h0 + grading·d, at most h,
/// scaled to end exactly there (at least one step).
std::vector<double> GradedSteps(double distance, double h0, double h, double grading) {
  std::vector<double> steps;
  if (!(distance > 0.0)) return steps;  // the crack reaches this face (through the thickness)
  double d = 0.0;
  while (d < distance) {
    const double step = std::min(h, h0 + grading * d);
    if (d + 0.5 * step > distance && !steps.empty()) break;  // the nearer end: stop short and stretch
    steps.push_back(step);
    d += step;
  }
  if (steps.empty()) steps.push_back(distance);
  for (double& s : steps) s *= distance / d;
  return steps;
}

/// Geometric layers from `first` growing by `growth` until they reach h0, then
/// GradedSteps from there: the heat grid's layers across the crack plane.
std::vector<double> LayeredSteps(double distance, double first, double growth, double h0, double h, double grading) {
  std::vector<double> steps;
  double d = 0.0;
  for (double step = first; step < h0 && d + step < 0.5 * distance; step *= growth) {
    steps.push_back(step);
    d += step;
  }
  const std::vector<double> rest = GradedSteps(distance - d, h0, h, grading);
  steps.insert(steps.end(), rest.begin(), rest.end());
  return steps;
}

/// The number of cells of size about h across `extent` (at least 1).
int CellsAcross(double extent, double h) { return std::max(1, static_cast<int>(std::lround(extent / h))); }

}  // namespace

std::vector<double> GradedAxis(double length, double b_lo, double b_hi, int cells, double h0, double h, double grading,
                               int* lo, int* hi, double first_layer, double growth) {
  const double start = cells > 0 ? (b_hi - b_lo) / cells : h0;
  const auto steps = [&](double distance) {
    return cells == 0 && first_layer > 0.0 ? LayeredSteps(distance, first_layer, growth, start, h, grading)
                                           : GradedSteps(distance, start, h, grading);
  };
  const std::vector<double> below = steps(b_lo), above = steps(length - b_hi);
  std::vector<double> nodes = {0.0};
  for (auto it = below.rbegin(); it != below.rend(); ++it) nodes.push_back(nodes.back() + *it);
  nodes.back() = b_lo;
  *lo = static_cast<int>(nodes.size()) - 1;
  for (int k = 1; k <= cells; ++k) nodes.push_back(k == cells ? b_hi : b_lo + k * start);
  *hi = static_cast<int>(nodes.size()) - 1;
  for (double step : above) nodes.push_back(nodes.back() + step);
  nodes.back() = length;
  return nodes;
}

BoxGrid::BoxGrid(const SpecimenGeometry& g) : BoxGrid(g, BoxGridSizes{g.h_crack, g.h, g.grading}) {}

BoxGrid::BoxGrid(const SpecimenGeometry& g, const BoxGridSizes& sizes) {
  validate(g);
  cracked_ = !g.cracks.empty();
  // Without a crack, a plane through the box's centre stands in for it: no cells on it,
  // no shear, no layers; every axis graded from -mesh_h on (uniform).
  Crack c;
  if (cracked_) c = g.cracks.front();
  else c.x = 0.5 * g.width, c.y = 0.5 * g.height, c.z = 0.5 * g.depth;
  const double h0 = cracked_ ? sizes.h_crack : sizes.h, first_layer = cracked_ ? sizes.first_layer : 0.0;
  const double theta = c.angle_deg * M_PI / 180.0;
  const bool steep = std::abs(std::cos(theta)) < std::sqrt(0.5) - 1e-12;
  p_ = steep ? 0 : 1;
  q_ = 1 - p_;
  slope_ = steep ? std::cos(theta) / std::sin(theta) : std::tan(theta);
  size_ = {g.width, g.height, g.depth};
  centre_ = {c.x, c.y, c.z};
  extent_[q_] = c.length * std::abs(steep ? std::sin(theta) : std::cos(theta));
  strike_per_q_ = 1.0 / std::abs(steep ? std::sin(theta) : std::cos(theta));
  extent_[p_] = 0.0;
  extent_[2] = c.width;
  normal_ = {-std::sin(theta), std::cos(theta), 0.0};
  std::array<int, 3> along{};
  along[q_] = cracked_ ? CellsAcross(c.length, sizes.h_crack) : 0;
  along[2] = cracked_ ? CellsAcross(c.width, sizes.h_crack) : 0;
  shape_ = c.shape;
  outline_cells_ = {CellsAcross(c.length, g.h_crack), CellsAcross(c.width, g.h_crack)};  // the wave grid's
  if (cracked_ && through_thickness(g)) centre_[2] = 0.5 * g.depth, extent_[2] = g.depth;  // ends exactly on the faces
  for (int a = 0; a < 3; ++a)
    nodes_[a] = GradedAxis(size_[a], centre_[a] - 0.5 * extent_[a], centre_[a] + 0.5 * extent_[a], along[a],
                           h0, sizes.h, sizes.grading, &crack_lo_[a], &crack_hi_[a], first_layer, sizes.growth);
  align_patch(g);
}

void BoxGrid::validate(const SpecimenGeometry& g) const {
  if (!(g.depth > 0.0) || !std::isfinite(g.depth)) reject("-specimen_depth must be > 0 for a 3D box, got ", g.depth);
  if (g.cracks.size() > 1)
    reject("-crack_center: a 3D specimen holds at most one crack for now (x,y,z of its centre), got ", g.cracks.size());
  g.validate();  // sizes, and the crack's trace in the x-y plane
  if (g.cracks.empty()) return;
  const Crack& c = g.cracks.front();
  if (!(c.width > 0.0) || !std::isfinite(c.width)) reject("-crack_width must be > 0 in 3D, got ", c.width);
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  const auto e0 = c.end(0), e1 = c.end(1);
  const bool inside_box = std::min({e0[0], e1[0], e0[1], e1[1]}) > tol && std::max(e0[0], e1[0]) < g.width - tol &&
                              std::max(e0[1], e1[1]) < g.height - tol;
  const double z0 = c.z - 0.5 * c.width, z1 = c.z + 0.5 * c.width;
  // z: buried, or through the thickness (exactly [0, D]: a plane-strain slab's crack).
  const bool z_ok = (z0 > tol && z1 < g.depth - tol) || through_thickness(g);
  if (!inside_box || !z_ok)
    reject("-crack_center/-crack_length/-crack_width: the crack reaches the outside of the specimen (3D cracks must ",
           "be buried in x-y and either buried in z or through the thickness, -crack_width = -specimen_depth centred ",
           "at z = depth/2; z extent [", z0, ", ", z1, "] of [0, ", g.depth, "])");
  if (c.shape == CrackShape::Ellipse && through_thickness(g))
    reject("-crack_shape ellipse: an elliptical crack must be buried (-crack_width < -specimen_depth); a crack through ",
           "the thickness is a rectangle");
  if (CellsAcross(c.length, g.h_crack) < 2)
    reject("-crack_length ", c.length, " m is resolved by fewer than 2 cells of -mesh_h_crack ", g.h_crack, " m");
  if (c.shape == CrackShape::Ellipse && std::min(CellsAcross(c.length, g.h_crack), CellsAcross(c.width, g.h_crack)) < 4)
    reject("-crack_shape ellipse: the ellipse needs at least 4 cells of -mesh_h_crack ", g.h_crack,
           " m across each axis (fewer make it its rectangle), got ", CellsAcross(c.length, g.h_crack), " x ",
           CellsAcross(c.width, g.h_crack));
  if (CellsAcross(c.width, g.h_crack) < 2 && !through_thickness(g))  // a through crack has no front along z
    reject("-crack_width ", c.width, " m is resolved by fewer than 2 cells of -mesh_h_crack ", g.h_crack, " m");
  // The shear x_p' = x_p + (x_q − c_q) m β(x_p) must not fold: |x_q − c_q| |m| max|β'| ≤ 3/4.
  const double theta = c.angle_deg * M_PI / 180.0;
  const bool steep = std::abs(std::cos(theta)) < std::sqrt(0.5) - 1e-12;
  const double m = std::abs(steep ? std::cos(theta) / std::sin(theta) : std::tan(theta));
  const double cp = steep ? c.x : c.y, cq = steep ? c.y : c.x;
  const double Lp = steep ? g.width : g.height, Lq = steep ? g.height : g.width;
  const double reach = std::max(cq, Lq - cq) * m * 0.5 * M_PI / std::min(cp, Lp - cp);
  if (reach > 0.75)
    reject("-crack_angle ", c.angle_deg, ": the 3D grid cannot be sheared into this crack plane without folding (the ",
           "crack centre lies ", std::min(cp, Lp - cp), " m from the faces normal to ", steep ? "x" : "y",
           "): a smaller inclination, or the crack farther from those faces");
}

bool BoxGrid::through_thickness(const SpecimenGeometry& g) {
  if (g.cracks.empty()) return false;
  const Crack& c = g.cracks.front();
  const double tol = 1e-9 * std::max({g.width, g.height, g.depth});
  return std::abs(c.z - 0.5 * c.width) <= tol && std::abs(c.z + 0.5 * c.width - g.depth) <= tol;
}

double BoxGrid::blend(double xp) const {
  const double d = xp < centre_[p_] ? centre_[p_] : size_[p_] - centre_[p_];
  const double c = std::cos(0.5 * M_PI * (xp - centre_[p_]) / d);
  return c * c;
}

std::array<double, 3> BoxGrid::position(const std::array<double, 3>& index) const {
  std::array<double, 3> x;
  for (int a = 0; a < 3; ++a) x[a] = nodes_[a][static_cast<std::size_t>(std::lround(index[a]))];
  x[p_] += (x[q_] - centre_[q_]) * slope_ * blend(x[p_]);
  return x;
}

bool BoxGrid::on_crack(const std::array<double, 3>& f) const {
  if (!cracked_) return false;
  const auto inside = [&](int a) { return f[a] > crack_lo_[a] && f[a] < crack_hi_[a]; };
  return std::abs(f[p_] - crack_lo_[p_]) < 1e-9 && inside(q_) && inside(2) && inside_outline(f);
}

bool BoxGrid::inside_outline(const std::array<double, 3>& f) const {
  if (shape_ == CrackShape::Rectangle) return true;
  // The crack's rectangle cut into the wave grid's uniform crack cells: the face is
  // kept when the cell holding its centre (by position, so that the wave grid and the
  // finer heat grid nested in it agree) has its centre in the ellipse.
  const int axes[2] = {q_, 2};
  double r2 = 0.0;
  for (int k = 0; k < 2; ++k) {
    const int a = axes[k];
    const std::size_t i = static_cast<std::size_t>(std::floor(f[a]));
    const double x = 0.5 * (nodes_[a][i] + nodes_[a][std::min(i + 1, nodes_[a].size() - 1)]);
    const double lo = nodes_[a][crack_lo_[a]], hi = nodes_[a][crack_hi_[a]];
    const double cell = std::floor((x - lo) / (hi - lo) * outline_cells_[k]);
    const double centre = (cell + 0.5) / outline_cells_[k];
    r2 += (2.0 * centre - 1.0) * (2.0 * centre - 1.0);
  }
  return r2 <= 1.0;
}

double BoxGrid::crack_area() const {
  if (!cracked_) return 0.0;
  double area = 0.0;
  for (int i = crack_lo_[q_]; i < crack_hi_[q_]; ++i)
    for (int j = crack_lo_[2]; j < crack_hi_[2]; ++j) {
      std::array<double, 3> f{};
      f[p_] = crack_lo_[p_], f[q_] = i + 0.5, f[2] = j + 0.5;
      if (on_crack(f)) area += (nodes_[q_][i + 1] - nodes_[q_][i]) * strike_per_q_ * (nodes_[2][j + 1] - nodes_[2][j]);
    }
  return area;
}

double BoxGrid::h_min() const {
  double h = INFINITY;
  for (const auto& axis : nodes_)
    for (std::size_t k = 1; k < axis.size(); ++k) h = std::min(h, axis[k] - axis[k - 1]);
  return h;
}

double BoxGrid::h_max() const {
  double h = 0.0;
  for (const auto& axis : nodes_)
    for (std::size_t k = 1; k < axis.size(); ++k) h = std::max(h, axis[k] - axis[k - 1]);
  return h;
}

}  // namespace vibrotherm::mesh

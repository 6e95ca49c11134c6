#include "vibrotherm/mesh/crack_line.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vibrotherm::mesh {

void CrackLine::Build(const std::vector<geometry::CrackFacet>& all, int crack) {
  std::map<long, std::array<double, 4>> facets;  // ordered by id
  for (const geometry::CrackFacet& f : all)
    if (f.crack == crack && f.id >= 0) facets[f.id] = {f.p0[0], f.p0[1], f.p1[0], f.p1[1]};
  points_.clear();
  arc_.clear();
  ids_.clear();
  length_ = 0.0;
  for (const auto& [id, f] : facets) {
    std::array<double, 2> a{f[0], f[1]}, b{f[2], f[3]};
    if (points_.empty()) {
      // Orient the first facet so that its second vertex touches the next facet.
      auto next = std::next(facets.find(id));
      if (next != facets.end()) {
        const auto& g = next->second;
        auto d = [](const std::array<double, 2>& p, double qx, double qy) { return std::hypot(p[0] - qx, p[1] - qy); };
        if (std::min(d(a, g[0], g[1]), d(a, g[2], g[3])) < std::min(d(b, g[0], g[1]), d(b, g[2], g[3])))
          std::swap(a, b);
      }
      points_.push_back(a);
      arc_.push_back(0.0);
    }
    const auto& last = points_.back();
    const std::array<double, 2> far =
        std::hypot(a[0] - last[0], a[1] - last[1]) < std::hypot(b[0] - last[0], b[1] - last[1]) ? b : a;
    ids_.push_back(static_cast<PetscInt>(id));
    length_ += std::hypot(far[0] - last[0], far[1] - last[1]);
    points_.push_back(far);
    arc_.push_back(length_);
  }
}

std::array<double, 2> CrackLine::At(double xi) const {
  if (points_.empty()) return {NAN, NAN};
  const double s = std::min(1.0, std::max(0.0, xi)) * length_;
  std::size_t k = std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin();
  if (k == 0) return points_.front();
  if (k >= points_.size()) return points_.back();
  const double w = (s - arc_[k - 1]) / std::max(arc_[k] - arc_[k - 1], 1e-300);
  return {points_[k - 1][0] + w * (points_[k][0] - points_[k - 1][0]),
          points_[k - 1][1] + w * (points_[k][1] - points_[k - 1][1])};
}

double CrackLine::XiOf(double x, double y) const {
  double best = INFINITY, xi = 0.0;
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const auto &p = points_[i], &q = points_[i + 1];
    const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
    const double s = len2 > 0.0 ? std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(x - p[0] - s * dx, y - p[1] - s * dy);
    if (d < best) best = d, xi = (arc_[i] + s * (arc_[i + 1] - arc_[i])) / length_;
  }
  return std::clamp(xi, 0.0, 1.0);
}

double CrackLine::Distance(double x, double y) const {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const auto &p = points_[i], &q = points_[i + 1];
    const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
    const double s = len2 > 0.0 ? std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(x - p[0] - s * dx, y - p[1] - s * dy));
  }
  return best;
}

}  // namespace vibrotherm::mesh

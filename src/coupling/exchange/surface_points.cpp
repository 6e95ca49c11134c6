#include "vibrotherm/coupling/exchange/surface_points.hpp"

#include <cmath>

namespace vibrotherm::coupling {

double SurfacePoints::total_area() const {
  double sum = 0.0;
  for (double a : area) sum += a;
  return sum;
}

SurfacePoints DiscSector(const geometry::Vec3& centre, const geometry::Frame<3>& frame, double radius, double theta0,
                         double theta1, int radial, int angular) {
  SurfacePoints points;
  const double dr = radius / radial, dtheta = (theta1 - theta0) / angular;
  for (int i = 0; i < radial; ++i) {
    const double r = (i + 0.5) * dr;
    for (int j = 0; j < angular; ++j) {
      const double theta = theta0 + (j + 0.5) * dtheta;
      const geometry::Vec3 in_plane = geometry::Add(geometry::Scale(r * std::cos(theta), frame.tangent[0]),
                                                    geometry::Scale(r * std::sin(theta), frame.tangent[1]));
      points.x.push_back(geometry::Add(centre, in_plane));
      points.area.push_back(r * dr * dtheta);
    }
  }
  return points;
}

SurfacePoints Rectangle(const geometry::Vec3& centre, const geometry::Frame<3>& frame, double h1, double h2, int n1,
                        int n2) {
  SurfacePoints points;
  const double d1 = 2.0 * h1 / n1, d2 = 2.0 * h2 / n2, g = 0.5 / std::sqrt(3.0);  // Gauss points at ½ ± g of a cell
  for (int i = 0; i < 2 * n1; ++i)
    for (int j = 0; j < 2 * n2; ++j) {
      const double u = -h1 + d1 * (i / 2 + 0.5 + (i % 2 ? g : -g)), v = -h2 + d2 * (j / 2 + 0.5 + (j % 2 ? g : -g));
      points.x.push_back(geometry::Add(centre, geometry::Add(geometry::Scale(u, frame.tangent[0]),
                                                             geometry::Scale(v, frame.tangent[1]))));
      points.area.push_back(0.25 * d1 * d2);
    }
  return points;
}

}  // namespace vibrotherm::coupling

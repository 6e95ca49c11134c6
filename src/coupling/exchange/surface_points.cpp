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

}  // namespace vibrotherm::coupling

// Points and vectors of D = 2 or 3 coordinates with the few operations crack
// geometry needs. Plain arrays, no PETSc: the same code serves the 2D specimen
// today and a 3D one later.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace vibrotherm::geometry {

template <std::size_t D>
using Point = std::array<double, D>;
using Vec2 = Point<2>;
using Vec3 = Point<3>;

template <std::size_t D>
Point<D> Add(const Point<D>& a, const Point<D>& b) {
  Point<D> r;
  for (std::size_t i = 0; i < D; ++i) r[i] = a[i] + b[i];
  return r;
}

template <std::size_t D>
Point<D> Sub(const Point<D>& a, const Point<D>& b) {
  Point<D> r;
  for (std::size_t i = 0; i < D; ++i) r[i] = a[i] - b[i];
  return r;
}

template <std::size_t D>
Point<D> Scale(double s, const Point<D>& a) {
  Point<D> r;
  for (std::size_t i = 0; i < D; ++i) r[i] = s * a[i];
  return r;
}

/// a · b, summed in index order.
template <std::size_t D>
double Dot(const Point<D>& a, const Point<D>& b) {
  double s = a[0] * b[0];
  for (std::size_t i = 1; i < D; ++i) s += a[i] * b[i];
  return s;
}

/// |a| by std::hypot (no overflow; in 2D the rounding the crack code has always used).
template <std::size_t D>
double Norm(const Point<D>& a) {
  static_assert(D == 2 || D == 3, "2D or 3D points");
  if constexpr (D == 2)
    return std::hypot(a[0], a[1]);
  else
    return std::hypot(a[0], a[1], a[2]);
}

/// a / |a|, component by component (a division, not a multiplication by 1/|a|).
template <std::size_t D>
Point<D> Normalized(const Point<D>& a) {
  const double n = Norm(a);
  Point<D> r;
  for (std::size_t i = 0; i < D; ++i) r[i] = a[i] / n;
  return r;
}

inline Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The z component of (a, 0) × (b, 0): positive when b lies counter-clockwise of a.
inline double Cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

}  // namespace vibrotherm::geometry

#include "vibrotherm/geometry/frame.hpp"

#include <cmath>

namespace vibrotherm::geometry {
namespace {

/// The coordinate axis least aligned with n (the first of equals): never nearly normal.
Vec3 LeastAlignedAxis(const Vec3& n) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
  Vec3 e{0.0, 0.0, 0.0};
  e[axis] = 1.0;
  return e;
}

}  // namespace

Frame<2> FrameFromNormal(const Vec2& normal) { return {normal, {Vec2{normal[1], -normal[0]}}}; }

Frame<2> FrameFromTangent(const Vec2& tangent) { return {LeftNormal(tangent), {tangent}}; }

Frame<3> FrameFromNormal(const Vec3& normal, const Vec3& reference) {
  const Vec3 n = Normalized(normal);
  Vec3 r = Normalized(reference);
  if (std::abs(Dot(r, n)) > kNearlyNormal) r = LeastAlignedAxis(n);
  const Vec3 t1 = Normalized(Sub(r, Scale(Dot(r, n), n)));
  return {n, {t1, Cross(n, t1)}};
}

Vec3 OrientedCrackNormal(const Vec3& normal) {
  const Vec3 n = Normalized(normal);
  const bool flip = std::abs(n[1]) > 1e-12 ? n[1] < 0.0 : std::abs(n[0]) > 1e-12 ? n[0] > 0.0 : n[2] < 0.0;
  return flip ? Scale(-1.0, n) : n;
}

Frame<3> CrackFrame(const Vec3& normal) {
  const Vec3 n = OrientedCrackNormal(normal);
  // The strike (n_y, −n_x, 0): already in the plane; a crack parallel to z = const has none,
  // its t1 is x.
  const bool flat = std::hypot(n[0], n[1]) < 1e-12;
  return FrameFromNormal(n, flat ? Vec3{1.0, 0.0, 0.0} : Vec3{n[1], -n[0], 0.0});
}

}  // namespace vibrotherm::geometry

// Local frames of a crack surface: a unit normal and D − 1 unit tangents,
// right-handed (2D: (t, n); 3D: (t1, t2, n)). The slip of contact laws is
// measured along the tangents, the opening along the normal.
//
// 2D keeps the convention of PHYSICS.md §3.1: n is the tangent s rotated by
// +90°, so from a normal the tangent is n rotated by −90°, s = (n_y, −n_x).
// 3D follows PyLith's fault up_dir and tandem's reference direction: t1 is the
// reference direction projected onto the crack plane (another coordinate axis
// when the reference is nearly normal to the plane), t2 = n × t1.
#pragma once

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::geometry {

template <std::size_t D>
struct Frame {
  Point<D> normal;
  std::array<Point<D>, D - 1> tangent;
};

/// s rotated by +90°: (−s_y, s_x), the crack normal of a 2D tangent.
inline Vec2 LeftNormal(const Vec2& s) { return {-s[1], s[0]}; }

/// The 2D frame of a unit normal: tangent n rotated by −90°. Exact: only signs change.
Frame<2> FrameFromNormal(const Vec2& normal);
/// The 2D frame of a unit tangent: normal s rotated by +90°.
Frame<2> FrameFromTangent(const Vec2& tangent);
/// The 3D frame of a unit normal; t1 along `reference` projected onto the plane.
Frame<3> FrameFromNormal(const Vec3& normal, const Vec3& reference = {0.0, 0.0, 1.0});

/// A 3D crack's unit normal oriented by the 2D convention extended: n_y > 0, or
/// n_x < 0 when n ⊥ y (for a crack plane containing z: its strike turned by +90°
/// about z), or n_z > 0 when n is ±z.
Vec3 OrientedCrackNormal(const Vec3& normal);
/// The frame of a 3D crack plane: the oriented normal, t1 its strike (horizontal: n turned
/// by −90° about z and projected, the 2D tangent; x for a plane z = const), t2 = n × t1
/// (−z for a plane containing z).
Frame<3> CrackFrame(const Vec3& normal);

/// |r̂ · n| above which a reference direction counts as normal to the plane.
inline constexpr double kNearlyNormal = 0.99;

}  // namespace vibrotherm::geometry

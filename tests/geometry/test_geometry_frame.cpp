// Requirement: crack frames are orthonormal and right-handed in 2D and 3D; the
// 2D frame is today's convention bit for bit (n = s turned by +90°, PHYSICS.md
// §3.1); the 3D t1 follows the reference direction projected onto the plane and
// falls back to a coordinate axis when the reference is nearly normal to it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "vibrotherm/geometry/frame.hpp"

namespace vibrotherm::geometry {
namespace {

constexpr double kTol = 1e-14;

Vec3 RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  return Normalized(Vec3{g(rng), g(rng), g(rng)});
}

void ExpectOrthonormal3(const Frame<3>& f) {
  const Vec3 v[3] = {f.tangent[0], f.tangent[1], f.normal};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(Dot(v[i], v[j]), i == j ? 1.0 : 0.0, kTol);
  const Vec3 t1xt2 = Cross(f.tangent[0], f.tangent[1]);  // right-handed: t1 × t2 = n
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(t1xt2[i], f.normal[i], kTol);
}

TEST(GeometryFrame2, IsTodaysConventionExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  for (int k = 0; k < 1000; ++k) {
    const double a = angle(rng);
    const Vec2 s{std::cos(a), std::sin(a)};
    const Vec2 n{-s[1], s[0]};  // the normal the contact code has always used
    const Frame<2> from_tangent = FrameFromTangent(s), from_normal = FrameFromNormal(n);
    EXPECT_EQ(from_tangent.normal, n);
    EXPECT_EQ(from_tangent.tangent[0], s);
    EXPECT_EQ(from_normal.tangent[0], s);
    EXPECT_EQ(from_normal.normal, n);
    EXPECT_EQ(LeftNormal(s), n);
  }
}

TEST(GeometryFrame2, IsOrthonormalAndRightHanded) {
  const Frame<2> f = FrameFromNormal(Normalized(Vec2{3.0, 4.0}));
  EXPECT_NEAR(Dot(f.normal, f.tangent[0]), 0.0, kTol);
  EXPECT_NEAR(Norm(f.tangent[0]), 1.0, kTol);
  EXPECT_NEAR(Cross(f.tangent[0], f.normal), 1.0, kTol);  // (t, n) counter-clockwise
  const Frame<2> horizontal = FrameFromTangent(Vec2{1.0, 0.0});
  EXPECT_EQ(horizontal.normal, (Vec2{-0.0, 1.0}));
}

TEST(GeometryFrame3, IsOrthonormalAndRightHandedForRandomNormals) {
  std::mt19937 rng(11);
  for (int k = 0; k < 1000; ++k) ExpectOrthonormal3(FrameFromNormal(RandomUnit(rng), RandomUnit(rng)));
}

TEST(GeometryFrame3, FirstTangentFollowsTheReferenceDirection) {
  // A vertical crack plane (normal x): up (z) lies in the plane, t1 = z, t2 = x × z = −y.
  const Frame<3> f = FrameFromNormal({1.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
  EXPECT_EQ(f.tangent[0], (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(f.tangent[1], (Vec3{0.0, -1.0, 0.0}));
  // A tilted reference: t1 is its projection, normalised, on the reference's side.
  std::mt19937 rng(3);
  for (int k = 0; k < 200; ++k) {
    const Vec3 n = RandomUnit(rng), r = RandomUnit(rng);
    if (std::abs(Dot(n, r)) > kNearlyNormal) continue;
    const Frame<3> g = FrameFromNormal(n, r);
    const Vec3 projected = Normalized(Sub(r, Scale(Dot(r, n), n)));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(g.tangent[0][i], projected[i], 1e-12);
    EXPECT_GT(Dot(g.tangent[0], r), 0.0);
  }
}

TEST(GeometryFrame3, FallsBackToAnAxisWhenTheReferenceIsNormal) {
  // A horizontal plane with the default reference z: t1 = the axis least aligned with n (x).
  const Frame<3> f = FrameFromNormal({0.0, 0.0, 1.0});
  EXPECT_EQ(f.tangent[0], (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(f.tangent[1], (Vec3{0.0, 1.0, 0.0}));
  ExpectOrthonormal3(f);
  // Nearly normal (|r̂·n| > 0.99): still a clean frame, no tiny projection blown up.
  ExpectOrthonormal3(FrameFromNormal(Normalized(Vec3{1e-3, 2e-3, 1.0}), {0.0, 0.0, 1.0}));
  ExpectOrthonormal3(FrameFromNormal(Normalized(Vec3{0.0, 1.0, 1e-9}), {0.0, 1.0, 0.0}));
}

TEST(GeometryFrame3, NormalisesItsInputs) {
  const Frame<3> f = FrameFromNormal({0.0, 2.0, 0.0}, {0.0, 0.0, 5.0});
  EXPECT_EQ(f.normal, (Vec3{0.0, 1.0, 0.0}));
  EXPECT_EQ(f.tangent[0], (Vec3{0.0, 0.0, 1.0}));
  ExpectOrthonormal3(f);
}

// The 3D crack convention extends 2D's: for a crack plane containing z with strike
// s = (cos θ, sin θ, 0), θ in (−90°, 90°], n = s turned by +90° about z, t1 = s, t2 = −z.
TEST(GeometryFrame3, CrackNormalFollowsThe2DConvention) {
  EXPECT_EQ(OrientedCrackNormal({1.0, 0.0, 0.0}), (Vec3{-1.0, 0.0, 0.0}));
  EXPECT_EQ(OrientedCrackNormal({-1.0, 0.0, 0.0}), (Vec3{-1.0, 0.0, 0.0}));
  for (double deg : {-80.0, -30.0, 0.0, 20.0, 45.0, 70.0, 89.0, 90.0}) {
    const double t = deg * M_PI / 180.0;
    const Vec3 s{std::cos(t), std::sin(t), 0.0}, n{-std::sin(t), std::cos(t), 0.0};
    for (double sign : {1.0, -1.0}) {
      const Frame<3> f = CrackFrame(Scale(sign, n));
      for (int d = 0; d < 3; ++d) {
        EXPECT_NEAR(f.normal[d], n[d], 1e-15) << deg << " deg";
        EXPECT_NEAR(f.tangent[0][d], s[d], 1e-15) << deg << " deg";
      }
      EXPECT_NEAR(f.tangent[1][2], -1.0, 1e-15) << deg << " deg";
      ExpectOrthonormal3(f);
    }
  }
}

// A tilted crack (-crack_tilt δ): n = cos δ (−sin θ, cos θ, 0) + sin δ ẑ keeps t1 = the strike
// (horizontal) and t2 = n × t1 in the plane; a crack parallel to z = const (δ = ±90°) gets
// n = +z whichever side its face normal came from, and t1 = x.
TEST(GeometryFrame3, TiltedAndFlatCracksKeepAStrike) {
  for (double tilt : {-60.0, 20.0, 89.0}) {
    const double t = 30.0 * M_PI / 180.0, d = tilt * M_PI / 180.0;
    const Vec3 s{std::cos(t), std::sin(t), 0.0};
    const Vec3 n{-std::sin(t) * std::cos(d), std::cos(t) * std::cos(d), std::sin(d)};
    for (double sign : {1.0, -1.0}) {
      const Frame<3> f = CrackFrame(Scale(sign, n));
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(f.normal[k], n[k], 1e-15) << tilt;
        EXPECT_NEAR(f.tangent[0][k], s[k], 1e-15) << tilt;
      }
      ExpectOrthonormal3(f);
    }
  }
  for (double sign : {1.0, -1.0}) {
    const Frame<3> f = CrackFrame({0.0, 0.0, sign});
    EXPECT_EQ(f.normal, (Vec3{0.0, 0.0, 1.0}));
    EXPECT_EQ(f.tangent[0], (Vec3{1.0, 0.0, 0.0}));
    ExpectOrthonormal3(f);
  }
}

}  // namespace
}  // namespace vibrotherm::geometry

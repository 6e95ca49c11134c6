// Requirement (issue 26, item 5: the camera films a face): on a 3D box, a camera on
// each of the six faces reads, pixel by pixel, the average over the pixel of the
// temperature on that face, in the face's (u, v) axes (camera_face.hpp). The field
// θ = 1 + 2x − 3y + 5z + 7xy − 11yz + 13xz is trilinear, so the Q1 and Q2 heat spaces
// hold it exactly, and the midpoint rule of the pixel's n × n sub-samples integrates its
// bilinear trace on any face exactly: every pixel equals the closed-form pixel mean to
// rounding, serial and on 2 ranks. A window in face coordinates selects those pixels;
// a face in 2D, an unknown face and a window off the face are refused naming the option.
#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <cmath>
#include <cstdio>

#include "box_mesh_support.hpp"
#include "vibrotherm/coupling/observe/heat_camera.hpp"

namespace vibrotherm::testing {
namespace {

constexpr double kSize[3] = {0.04, 0.03, 0.02};  // box [0, 4 cm] × [0, 3 cm] × [0, 2 cm]

double Theta(double x, double y, double z) { return 1 + 2 * x - 3 * y + 5 * z + 7 * x * y - 11 * y * z + 13 * x * z; }

/// The mean of θ over the pixel [u0, u1] × [v0, v1] of a face: θ is bilinear on it, so its centre value
/// (on the plane the camera samples: 1e-9 of the box inside the face, camera_face.hpp).
double PixelMean(const std::string& face, double u0, double v0, double u1, double v1) {
  const double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1), hair = 1e-9 * kSize[0];
  const auto at = [&](int axis, bool upper) { return upper ? kSize[axis] - hair : hair; };
  if (face == "front" || face == "back") return Theta(u, v, at(2, face == "front"));
  if (face == "top" || face == "bottom") return Theta(u, at(1, face == "top"), v);
  return Theta(at(0, face == "right"), v, u);  // left, right: u = z, v = y
}

struct FaceCase {
  std::string face;
  int degree;
};

class CameraFaceTest : public ::testing::TestWithParam<FaceCase> {
 protected:
  void SetUp() override {
    const PetscInt faces[3] = {8, 6, 4};
    const PetscReal lower[3] = {0, 0, 0}, upper[3] = {kSize[0], kSize[1], kSize[2]};
    ASSERT_EQ(DMPlexCreateBoxMesh(PETSC_COMM_WORLD, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, &dm_), 0);
    DM distributed = nullptr;
    ASSERT_EQ(DMPlexDistribute(dm_, 0, nullptr, &distributed), 0);
    if (distributed) {
      DMDestroy(&dm_);
      dm_ = distributed;
    }
    ASSERT_EQ(space_.Setup(dm_, GetParam().degree, 1), 0);
    ASSERT_EQ(NodalField(space_, [](const double* x, double* v) { v[0] = Theta(x[0], x[1], x[2]); }, &theta_), 0);
  }
  void TearDown() override {
    VecDestroy(&theta_);
    DMDestroy(&dm_);
  }
  /// Every pixel against its closed-form mean: the largest difference relative to θ's range.
  double WorstPixel(const coupling::HeatCamera& camera, const std::string& face) {
    Vec pixels, all;
    VecScatter to_all;
    MatCreateVecs(camera.pixel_matrix(), nullptr, &pixels);
    MatMult(camera.pixel_matrix(), theta_, pixels);
    VecScatterCreateToAll(pixels, &to_all, &all);
    VecScatterBegin(to_all, pixels, all, INSERT_VALUES, SCATTER_FORWARD);
    VecScatterEnd(to_all, pixels, all, INSERT_VALUES, SCATTER_FORWARD);
    const PetscScalar* p;
    VecGetArrayRead(all, &p);
    const io::CameraGrid& g = camera.grid();
    double worst = 0.0;
    for (std::size_t r = 0; r < g.rows; ++r)
      for (std::size_t c = 0; c < g.cols; ++c) {
        const double u0 = g.x0 + c * g.pixel, v0 = g.y0 + r * g.pixel;
        worst = std::max(worst, std::abs(p[r * g.cols + c] - PixelMean(face, u0, v0, u0 + g.pixel, v0 + g.pixel)));
      }
    VecRestoreArrayRead(all, &p);
    VecScatterDestroy(&to_all);
    VecDestroy(&all);
    VecDestroy(&pixels);
    return worst;
  }
  DM dm_ = nullptr;
  fe::LagrangeSpace space_;
  Vec theta_ = nullptr;
};

TEST_P(CameraFaceTest, PixelsAreTheFaceMeansOfTheTemperature) {
  coupling::CameraOptions options;
  options.face = GetParam().face;
  options.pixel = 2e-3;
  options.samples = 3;
  coupling::HeatCamera camera;
  PetscInt frames;
  ASSERT_EQ(camera.Setup(space_, options, 1.0, &frames), 0);
  ASSERT_GT(frames, 0);
  const io::CameraGrid& g = camera.grid();
  const bool side = options.face == "left" || options.face == "right";
  const bool top = options.face == "top" || options.face == "bottom";
  // The whole face in 2 mm pixels: u spans x (z on the sides), v spans y (z on top and bottom).
  EXPECT_EQ(g.cols, static_cast<std::size_t>(std::lround((side ? kSize[2] : kSize[0]) / 2e-3)));
  EXPECT_EQ(g.rows, static_cast<std::size_t>(std::lround((top ? kSize[2] : kSize[1]) / 2e-3)));
  const double worst = WorstPixel(camera, options.face);
  std::printf("  %s, degree %d: %zu x %zu pixels, worst |pixel - mean| %.2e K\n", options.face.c_str(),
              GetParam().degree, g.rows, g.cols, worst);
  EXPECT_LT(worst, 1e-12);
}

TEST_P(CameraFaceTest, AWindowInFaceCoordinatesSelectsItsPixels) {
  coupling::CameraOptions options;
  options.face = GetParam().face;
  options.pixel = 1e-3;
  options.samples = 2;
  options.window = {0.002, 0.003, 0.012, 0.009};  // (u0, v0, u1, v1): inside every face of this box
  coupling::HeatCamera camera;
  PetscInt frames;
  ASSERT_EQ(camera.Setup(space_, options, 1.0, &frames), 0);
  EXPECT_EQ(camera.grid().cols, 10u);
  EXPECT_EQ(camera.grid().rows, 6u);
  EXPECT_NEAR(camera.grid().x0, 0.002, 1e-15);
  EXPECT_LT(WorstPixel(camera, options.face), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Faces, CameraFaceTest,
                         ::testing::Values(FaceCase{"front", 1}, FaceCase{"back", 2}, FaceCase{"top", 1},
                                           FaceCase{"bottom", 2}, FaceCase{"left", 1}, FaceCase{"right", 2}),
                         [](const ::testing::TestParamInfo<FaceCase>& info) {
                           return info.param.face + "_q" + std::to_string(info.param.degree);
                         });

TEST(CameraFaceInput, RefusedNamingTheOption) {
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  DM dm2, dm3;
  const PetscInt faces[3] = {4, 4, 4};
  DMPlexCreateBoxMesh(PETSC_COMM_WORLD, 2, PETSC_FALSE, faces, nullptr, nullptr, nullptr, PETSC_TRUE, &dm2);
  DMPlexCreateBoxMesh(PETSC_COMM_WORLD, 3, PETSC_FALSE, faces, nullptr, nullptr, nullptr, PETSC_TRUE, &dm3);
  coupling::CameraFace face;
  EXPECT_NE(face.Setup(dm2, "front"), 0);  // 2D: the plane itself
  EXPECT_EQ(face.Setup(dm2, ""), 0);
  EXPECT_NE(face.Setup(dm3, "side"), 0);  // unknown
  EXPECT_EQ(face.Setup(dm3, "top"), 0);
  fe::LagrangeSpace space;
  space.Setup(dm3, 1, 1);
  coupling::CameraOptions options;
  options.window = {0.5, 0.5, 1.5, 0.9};  // beyond the unit face
  coupling::HeatCamera camera;
  PetscInt frames;
  EXPECT_NE(camera.Setup(space, options, 1.0, &frames), 0);
  PetscPopErrorHandler();
  DMDestroy(&dm2);
  DMDestroy(&dm3);
}

}  // namespace
}  // namespace vibrotherm::testing

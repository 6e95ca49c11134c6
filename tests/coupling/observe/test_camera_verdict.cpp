// Requirement (issue 43, item 1): the camera's verdict is about the defect. A frame's signal is
// the defect's own share d of the rise c; the background c − d (damping heat at a corner) may
// be hotter, and then the defect does not stand out; the hottest pixel is said to be the
// defect's only where the defect makes at least half of it; with nothing heating at the crack
// (d = 0) nothing is detectable however hot the frame.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vibrotherm/coupling/observe/camera_verdict.hpp"

namespace vibrotherm::coupling {
namespace {

TEST(CameraVerdict, SignalBackgroundAndTheHottestPixel) {
  // 4 pixels: the crack under pixel 1 (0.3 K of its own), damping heat 0.5 K at the corner (pixel 3).
  const std::vector<double> c = {0.1, 0.4, 0.1, 0.5}, d = {0.0, 0.3, 0.05, 0.0};
  const FrameVerdict f = Judge(0.01, c, &d);
  EXPECT_DOUBLE_EQ(f.total_peak, 0.5);
  EXPECT_DOUBLE_EQ(f.total_pixel, 3);
  EXPECT_DOUBLE_EQ(f.defect_peak, 0.3);
  EXPECT_DOUBLE_EQ(f.defect_pixel, 1);
  EXPECT_DOUBLE_EQ(f.background_peak, 0.5);
  EXPECT_DOUBLE_EQ(f.defect_at_total_peak, 0.0);
  const DefectVerdict v = Summarise({f}, {0.02, 5.0, 1.0});
  EXPECT_NEAR(v.peak_snr, 15.0, 1e-12);
  EXPECT_NEAR(v.contrast, 0.6, 1e-12);
  EXPECT_FALSE(v.detectable);  // above the noise, but the corner outshines it
  EXPECT_FALSE(v.peak_on_defect);
  EXPECT_TRUE(Summarise({f}, {0.02, 5.0, 0.5}).detectable);  // a lower contrast asked: seen
}

TEST(CameraVerdict, NothingAtTheCrackIsNeverDetectable) {
  const std::vector<double> c = {462.0, 10.0}, none;
  const FrameVerdict f = Judge(1.0, c, &none);
  const DefectVerdict v = Summarise({f, f}, {0.02, 5.0, 0.0});
  EXPECT_EQ(v.peak_snr, 0.0);
  EXPECT_FALSE(v.detectable);
  EXPECT_EQ(v.detection_time, -1.0);
  EXPECT_FALSE(v.peak_on_defect);
}

TEST(CameraVerdict, OnlyTheCrackHeatsTheFirstFrameAboveTheNoiseDetects) {
  std::vector<FrameVerdict> frames;
  for (int k = 0; k < 5; ++k) {
    const std::vector<double> c = {0.0, 0.03 * k};
    frames.push_back(Judge(0.01 * (k + 1), c, nullptr));  // d = c: the crack the only heat
  }
  const DefectVerdict v = Summarise(frames, {0.02, 5.0, 1.0});
  EXPECT_TRUE(std::isinf(v.contrast));  // no background at all
  EXPECT_TRUE(v.detectable);
  EXPECT_DOUBLE_EQ(v.detection_time, 0.05);  // SNR 0, 1.5, 3, 4.5, 6: the fifth frame's end
  EXPECT_TRUE(v.peak_on_defect);
  EXPECT_EQ(v.peak_frame, 4u);
}

}  // namespace
}  // namespace vibrotherm::coupling

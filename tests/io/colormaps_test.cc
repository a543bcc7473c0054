#include "io/colormaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace msp {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kThresholds[2] = {0.01, 0.05};

// The polynomial stays close to the original Turbo table, which OpenCV ships
// (a wrong coefficient moves whole stretches of it).
TEST(Colormaps, TurboFollowsTheOriginalTable) {
  constexpr double kMaxMeanLevelDifference = 7.0;
  constexpr int kMaxLevelDifference = 32;  // at the dark ends, where the fit is loosest
  cv::Mat levels(1, 256, CV_8UC1), bgr;
  for (int i = 0; i < 256; ++i) levels.at<uint8_t>(0, i) = static_cast<uint8_t>(i);
  cv::applyColorMap(levels, bgr, cv::COLORMAP_TURBO);
  int worst = 0, sum = 0;
  for (int i = 0; i < 256; ++i) {
    const Rgb ours = TurboColor(i / 255.0f);
    const cv::Vec3b table = bgr.at<cv::Vec3b>(0, i);
    for (const int difference :
         {std::abs(ours.r - table[2]), std::abs(ours.g - table[1]), std::abs(ours.b - table[0])}) {
      worst = std::max(worst, difference);
      sum += difference;
    }
  }
  EXPECT_LE(sum / (256.0 * 3), kMaxMeanLevelDifference);
  EXPECT_LE(worst, kMaxLevelDifference);
  EXPECT_EQ(TurboColor(-3.0f), TurboColor(0.0f));  // clamped
  EXPECT_EQ(TurboColor(7.0f), TurboColor(1.0f));
}

TEST(Colormaps, DepthIsRedNearBlueFarAndBlackWithoutDepth) {
  const DepthRange range{2.0f, 6.0f};
  const Rgb near = DepthColor(2.0f, range), far = DepthColor(6.0f, range);
  EXPECT_GT(near.r, 2 * near.b);
  EXPECT_GT(far.b, 2 * far.r);
  EXPECT_GE(far.b, 128) << "the far end must not look like the black of no depth";
  EXPECT_EQ(DepthColor(1.0f, range), near);  // beyond the range: its ends
  EXPECT_EQ(DepthColor(60.0f, range), far);
  EXPECT_NE(DepthColor(4.0f, range), near);
  EXPECT_NE(DepthColor(4.0f, range), far);
  for (float none : {0.0f, -1.0f, kNaN, kInf}) EXPECT_EQ(DepthColor(none, range), Rgb{});
  EXPECT_EQ(DepthColor(3.0f, DepthRange{3.0f, 3.0f}), TurboColor(0.5f));  // one depth only
}

TEST(Colormaps, NormalIsHalfOffsetRgbAndBlackWhenZero) {
  const uint8_t half = ToByte(0.5f);
  EXPECT_EQ(NormalColor(0.0f, 0.0f, -1.0f), (Rgb{half, half, 0}));  // facing the camera
  EXPECT_EQ(NormalColor(1.0f, 0.0f, 0.0f), (Rgb{255, half, half}));
  EXPECT_EQ(NormalColor(0.0f, -1.0f, 0.0f), (Rgb{half, 0, half}));
  EXPECT_EQ(NormalColor(0.0f, 0.0f, 0.0f), Rgb{});
}

// The classes use the evaluator's tests: a threshold itself still counts as
// within it, and a pixel without ground truth is never an error.
TEST(Colormaps, DepthErrorClassesFollowTheEvaluatorsThresholds) {
  EXPECT_EQ(ClassifyDepthError(2.0f, 0.0f, kThresholds), DepthErrorClass::kNoGroundTruth);
  EXPECT_EQ(ClassifyDepthError(0.0f, kNaN, kThresholds), DepthErrorClass::kNoGroundTruth);
  EXPECT_EQ(ClassifyDepthError(0.0f, 2.0f, kThresholds), DepthErrorClass::kMissing);
  EXPECT_EQ(ClassifyDepthError(kNaN, 2.0f, kThresholds), DepthErrorClass::kMissing);
  EXPECT_EQ(ClassifyDepthError(2.0f, 2.0f, kThresholds), DepthErrorClass::kAccurate);
  EXPECT_EQ(ClassifyDepthError(4.0f, 4.0f * 1.009f, kThresholds), DepthErrorClass::kAccurate);
  EXPECT_EQ(ClassifyDepthError(1.011f, 1.0f, kThresholds), DepthErrorClass::kClose);
  EXPECT_EQ(ClassifyDepthError(0.951f, 1.0f, kThresholds), DepthErrorClass::kClose);
  EXPECT_EQ(ClassifyDepthError(1.051f, 1.0f, kThresholds), DepthErrorClass::kWrong);
  EXPECT_EQ(ClassifyDepthError(4.0f, 2.0f, kThresholds), DepthErrorClass::kWrong);
  // Where nothing is (an exact render's 0), a depth is its own class.
  EXPECT_EQ(ClassifyDepthError(2.0f, 0.0f, kThresholds, true), DepthErrorClass::kOnEmpty);
  EXPECT_EQ(ClassifyDepthError(0.0f, 0.0f, kThresholds, true), DepthErrorClass::kNoGroundTruth);
  EXPECT_NE(DepthErrorColor(DepthErrorClass::kOnEmpty), DepthErrorColor(DepthErrorClass::kWrong));
  EXPECT_NE(DepthErrorColor(DepthErrorClass::kOnEmpty), Rgb{});
  const double wide[2] = {0.5, 1.0};  // a scene.json may set its own
  EXPECT_EQ(ClassifyDepthError(1.5f, 1.0f, wide), DepthErrorClass::kAccurate);  // exactly 0.5
  EXPECT_EQ(ClassifyDepthError(2.0f, 1.0f, wide), DepthErrorClass::kClose);     // exactly 1
}

TEST(Colormaps, ErrorColoursAreTrafficLightsGreyAndBlack) {
  const Rgb green = DepthErrorColor(DepthErrorClass::kAccurate);
  const Rgb yellow = DepthErrorColor(DepthErrorClass::kClose);
  const Rgb red = DepthErrorColor(DepthErrorClass::kWrong);
  const Rgb grey = DepthErrorColor(DepthErrorClass::kMissing);
  EXPECT_EQ(DepthErrorColor(DepthErrorClass::kNoGroundTruth), Rgb{});
  EXPECT_TRUE(green.g > 128 && green.r < 64 && green.b < 64);
  EXPECT_TRUE(yellow.r > 128 && yellow.g > 128 && yellow.b < 64);
  EXPECT_TRUE(red.r > 128 && red.g < 64 && red.b < 64);
  EXPECT_TRUE(grey.r == grey.g && grey.g == grey.b && grey.r > 64 && grey.r < 192);
}

}  // namespace
}  // namespace msp

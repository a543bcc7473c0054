#include "core/reliability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plane_scene.h"

namespace msp {
namespace core {
namespace {

// A V-shaped curve with its minimum `cost` at sample `at` (slope per sample).
std::vector<float> VCurve(int at, float cost, float slope) {
  std::vector<float> c(kCurveSamples);
  for (int i = 0; i < kCurveSamples; ++i) c[i] = cost + slope * std::abs(i - at);
  return c;
}

constexpr int kCentre = kCurveHalfWidth;
constexpr float kSlope = 0.02f;

uint8_t Classify(const std::vector<float>& c, int pass) {
  return ClassifyCostCurve(c.data(), static_cast<int>(c.size()), DefaultReliabilityParams(pass));
}

TEST(Reliability, RadiiFollowThePassSchedule) {
  EXPECT_EQ(ReliabilityRadius(0), 6);
  EXPECT_EQ(ReliabilityRadius(1), 4);
  EXPECT_EQ(ReliabilityRadius(2), 2);
  EXPECT_EQ(ReliabilityRadius(3), 2);
  EXPECT_EQ(ReliabilityRadius(7), 2);
}

TEST(Reliability, SingleSharpLowMinimumIsReliable) {
  EXPECT_EQ(Classify(VCurve(kCentre, 0.05f, kSlope), 0), kReliable);
  EXPECT_EQ(Classify(VCurve(kCentre, 0.15f, kSlope), 0), kReliable);
}

TEST(Reliability, SingleMinimumTooHighIsUnreliable) {
  EXPECT_EQ(Classify(VCurve(kCentre, 0.3f, kSlope), 0), kUnreliable);  // above 0.15
  EXPECT_EQ(Classify(VCurve(kCentre, 0.6f, kSlope), 0), kUnreliable);  // above 0.5
}

TEST(Reliability, MinimumFarFromTheCentreIsUnreliable) {
  EXPECT_EQ(Classify(VCurve(kCentre + 5, 0.05f, kSlope), 0), kReliable);    // radius 6
  EXPECT_EQ(Classify(VCurve(kCentre + 5, 0.05f, kSlope), 1), kUnreliable);  // radius 4
  EXPECT_EQ(Classify(VCurve(kCentre - 3, 0.05f, kSlope), 2), kUnreliable);  // radius 2
  EXPECT_EQ(Classify(VCurve(kCentre - 2, 0.05f, kSlope), 3), kReliable);
  EXPECT_EQ(Classify(VCurve(kCentre + 20, 0.05f, kSlope), 0), kUnreliable);
}

TEST(Reliability, FlatCurveIsUnreliable) {
  EXPECT_EQ(Classify(std::vector<float>(kCurveSamples, 0.1f), 0), kUnreliable);
  EXPECT_EQ(Classify(std::vector<float>(kCurveSamples, kMaxCost), 0), kUnreliable);
}

TEST(Reliability, TwoMinimaNeedASpread) {
  // Lowest at the centre (0.1), a second minimum at +15 px.
  std::vector<float> c = VCurve(kCentre, 0.1f, kSlope);
  for (int i = kCentre + 8; i < kCurveSamples; ++i)
    c[i] = 0.4f + kSlope * std::abs(i - (kCentre + 15));
  EXPECT_EQ(Classify(c, 0), kReliable);  // second minimum 0.3 above the lowest
  for (int i = kCentre + 8; i < kCurveSamples; ++i)
    c[i] = 0.2f + kSlope * std::abs(i - (kCentre + 15));
  EXPECT_EQ(Classify(c, 0), kUnreliable);  // only 0.1 above: ambiguous
  // A distinct lowest minimum that is itself too costly stays unreliable.
  c = VCurve(kCentre, 0.55f, kSlope);
  for (int i = kCentre + 8; i < kCurveSamples; ++i)
    c[i] = 1.5f + kSlope * std::abs(i - (kCentre + 15));
  EXPECT_EQ(Classify(c, 0), kUnreliable);
}

TEST(Reliability, ThresholdsAreParameters) {
  ReliabilityParams loose = DefaultReliabilityParams(0);
  loose.single_min_cost = 0.35f;
  const std::vector<float> c = VCurve(kCentre, 0.3f, kSlope);
  EXPECT_EQ(ClassifyCostCurve(c.data(), kCurveSamples, loose), kReliable);
}

TEST(Reliability, TexturedPlaneAtItsTrueDepthIsReliable) {
  testing_scene::PlaneScene s;
  testing_scene::MakeScene(4.0f, true, &s);
  float curve[kCurveSamples];
  ASSERT_TRUE(SampleCostCurve(s.params, 100, 75, curve));
  EXPECT_LT(curve[kCentre], 0.05f);
  EXPECT_EQ(ClassifyPixel(s.params, 100, 75, DefaultReliabilityParams(0)), kReliable);
  EXPECT_EQ(ClassifyPixel(s.params, 60, 50, DefaultReliabilityParams(3)), kReliable);
}

TEST(Reliability, TexturelessPlaneIsUnreliable) {
  testing_scene::PlaneScene s;
  testing_scene::MakeScene(4.0f, false, &s);
  EXPECT_EQ(ClassifyPixel(s.params, 100, 75, DefaultReliabilityParams(0)), kUnreliable);
}

TEST(Reliability, BorderNoDepthOrNoViewIsUnknown) {
  testing_scene::PlaneScene s;
  testing_scene::MakeScene(4.0f, true, &s);
  const ReliabilityParams rp = DefaultReliabilityParams(0);
  EXPECT_EQ(ClassifyPixel(s.params, 2, 75, rp), kUnknown);  // window over the border
  EXPECT_EQ(ClassifyPixel(s.params, 100, 147, rp), kUnknown);
  const int i = s.params.state.Index(100, 75);
  s.state_mask[i] = 0u;
  EXPECT_EQ(ClassifyPixel(s.params, 100, 75, rp), kUnknown);  // no selected view
  s.state_mask[i] = 1u;
  s.state_depth[i] = 0.0f;
  EXPECT_EQ(ClassifyPixel(s.params, 100, 75, rp), kUnknown);  // no depth
}

}  // namespace
}  // namespace core
}  // namespace msp

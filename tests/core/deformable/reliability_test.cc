#include "core/deformable/reliability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/plane_scene.h"

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
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  CostCurveSampler sampler;
  ASSERT_TRUE(sampler.Prepare(s.params, 100, 75));
  EXPECT_LT(sampler.At(kCentre), 0.05f);
  EXPECT_EQ(ClassifyPixel(s.params, 100, 75, DefaultReliabilityParams(0)), kReliable);
  EXPECT_EQ(ClassifyPixel(s.params, 60, 50, DefaultReliabilityParams(3)), kReliable);
}

// The sampler scores its samples in blocks (one vector lane each): every
// sample costs what the view-weighted cost of its plane alone gives.
TEST(Reliability, BlockScoredCurveEqualsEachSampleAlone) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
  for (const int col : {100, 60}) {
    CostCurveSampler sampler;
    ASSERT_TRUE(sampler.Prepare(s.params, col, 75));
    RefWindow w;
    PrepareWindow(s.params, col, 75, &w);
    int in_range = 0;
    // Out of order, so that blocks are filled from either end.
    for (int i = 0; i < kCurveSamples; ++i) {
      const int k = (i * 37) % kCurveSamples;
      const PlaneHypothesis h = sampler.Plane(k);
      float alone = kMaxCost;
      if (DepthInRange(s.params, h.depth)) {
        const PreparedPlane plane = PreparePlane(s.params, col, 75, h);
        float costs[kMaxSourceViews];
        for (int j = 0; j < s.params.num_src; ++j) {
          costs[j] = PhotometricViewCost(s.params, w, j, plane);
        }
        alone = AggregateCost(costs, sampler.weights(), s.params.num_src);
        ++in_range;
      }
      EXPECT_NEAR(sampler.At(k), alone, 2e-4f) << col << " sample " << k;
    }
    EXPECT_GT(in_range, 20);
  }
}

TEST(Reliability, TexturelessPlaneIsUnreliable) {
  test::PlaneScene s;
  test::MakeScene(4.0f, false, &s);
  EXPECT_EQ(ClassifyPixel(s.params, 100, 75, DefaultReliabilityParams(0)), kUnreliable);
}

TEST(Reliability, BorderNoDepthOrNoViewIsUnknown) {
  test::PlaneScene s;
  test::MakeScene(4.0f, true, &s);
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

namespace msp {
namespace core {
namespace {

// Serves a stored curve and counts the samples asked for. With `bounding`
// set, a cost above the floor asked for comes back as an arbitrary lower
// bound above that floor, as the real sampler may give it.
struct CountingSampler {
  const std::vector<float>* curve;
  uint64_t bounding = 0;
  int calls = 0;
  int bounds = 0;
  float AtLeast(int i, float floor) {
    ++calls;
    const float cost = (*curve)[i];
    if (bounding == 0 || !(cost > floor)) return cost;
    ++bounds;
    const float bound = floor + (cost - floor) * RandomUniform(Mix64(bounding), i);
    return bound > floor ? bound : cost;
  }
};

uint8_t ClassifyLazily(const std::vector<float>& c, const ReliabilityParams& params, int* calls,
                       uint64_t bounding = 0, int* bounds = nullptr) {
  CountingSampler sampler{&c, bounding};
  LazyCostCurve<CountingSampler> curve(&sampler, static_cast<int>(c.size()));
  const uint8_t result = ClassifyCostCurveLazily(curve, params);
  *calls = sampler.calls;
  if (bounds != nullptr) *bounds = sampler.bounds;
  return result;
}

TEST(Reliability, LazyClassificationAgreesWithTheWholeCurve) {
  // Random curves of coarse values (so ties and plateaus happen); every other
  // one lies higher with a deep minimum planted near the centre, under every
  // pass's radius.
  int reliable = 0, unreliable = 0, bounded = 0;
  for (uint64_t trial = 0; trial < 4000; ++trial) {
    std::vector<float> c(kCurveSamples);
    const bool planted = trial % 2 == 0;
    for (int i = 0; i < kCurveSamples; ++i) {
      c[i] = (planted ? 0.5f : 0.0f) + 0.05f * std::floor(20.0f * RandomUniform(Mix64(trial), i));
    }
    if (planted) {
      const int at = kCentre - 3 + static_cast<int>(trial / 2 % 7);
      c[at] = 0.05f * static_cast<float>(trial / 14 % 4);
    }
    for (int pass = 0; pass < 4; ++pass) {
      const ReliabilityParams params = DefaultReliabilityParams(pass);
      int calls = 0;
      const uint8_t lazy = ClassifyLazily(c, params, &calls);
      ASSERT_EQ(lazy, ClassifyCostCurve(c.data(), kCurveSamples, params)) << trial << " " << pass;
      ASSERT_LE(calls, kCurveSamples);
      reliable += lazy == kReliable;
      unreliable += lazy == kUnreliable;
      // Lower bounds in place of the costs the verdict does not need.
      int bounds = 0;
      ASSERT_EQ(ClassifyLazily(c, params, &calls, trial + 1, &bounds), lazy)
          << trial << " " << pass;
      ASSERT_LE(calls, kCurveSamples);
      bounded += bounds;
    }
  }
  EXPECT_GT(reliable, 100);  // both outcomes were exercised
  EXPECT_GT(unreliable, 100);
  EXPECT_GT(bounded, 1000);  // and bounds stood in for many costs
}

TEST(Reliability, LowerBoundsStandInOnlyWhereTheVerdictAllows) {
  int calls = 0, bounds = 0;
  for (uint64_t seed = 1; seed <= 50; ++seed) {
    // A single minimum low enough to be reliable alone: the samples away
    // from it may come back as bounds.
    EXPECT_EQ(ClassifyLazily(VCurve(kCentre, 0.1f, kSlope), DefaultReliabilityParams(0), &calls,
                             seed, &bounds),
              kReliable);
    EXPECT_GT(bounds, 0);
    // A single minimum too high for that: whether another minimum exists
    // decides, so bounds, which could fake one, must not be used.
    EXPECT_EQ(ClassifyLazily(VCurve(kCentre, 0.3f, kSlope), DefaultReliabilityParams(0), &calls,
                             seed, &bounds),
              kUnreliable);
    EXPECT_EQ(bounds, 0);
  }
}

TEST(Reliability, LazyClassificationStopsEarlyOnFlatOrDistantMinima) {
  int calls = 0;
  const std::vector<float> flat(kCurveSamples, 0.9f);
  EXPECT_EQ(ClassifyLazily(flat, DefaultReliabilityParams(2), &calls), kUnreliable);
  EXPECT_LE(calls, 2 * 2 + 3);  // at most the central range and a sample either side
  EXPECT_EQ(
      ClassifyLazily(VCurve(kCentre + 20, 0.05f, kSlope), DefaultReliabilityParams(0), &calls),
      kUnreliable);
  EXPECT_LE(calls, 2 * 6 + 3);
  // A reliable pixel needs the whole curve to rule out competitors.
  EXPECT_EQ(ClassifyLazily(VCurve(kCentre, 0.05f, kSlope), DefaultReliabilityParams(0), &calls),
            kReliable);
  EXPECT_EQ(calls, kCurveSamples);
}

}  // namespace
}  // namespace core
}  // namespace msp

#include "tools/evaluate/evaluate_depth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace msp {
namespace eval {
namespace {

// 1 % / 5 % relative, 2 cm / 5 cm absolute.
const DepthThresholds kThresholds;

// Ground truth: depth 2 + col / 100, normal (0, 0, -1); textureless on the
// left half.
struct GroundTruth {
  DenseMap depth{8, 6, 1};
  DenseMap normal{8, 6, 3};
  RegionMasks masks;
  GroundTruth() {
    masks.textureless = cv::Mat(6, 8, CV_8UC1, cv::Scalar(0));
    for (int r = 0; r < depth.height; ++r) {
      for (int c = 0; c < depth.width; ++c) {
        depth.At(r, c) = 2.0f + 0.01f * c;
        normal.At(r, c, 2) = -1.0f;
        if (c < depth.width / 2) masks.textureless.at<uint8_t>(r, c) = 255;
      }
    }
  }
};

TEST(EvaluateDepthMap, GroundTruthAgainstItselfIsPerfect) {
  const GroundTruth gt;
  const DepthMapMetrics m =
      EvaluateDepthMap(gt.depth, gt.normal, gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_EQ(m.all.num_gt, 48);
  EXPECT_EQ(m.textureless.num_gt, 24);
  EXPECT_EQ(m.textured.num_gt, 24);
  for (const RegionMetrics* r : {&m.all, &m.textureless, &m.textured}) {
    EXPECT_DOUBLE_EQ(r->valid_fraction, 1.0);
    EXPECT_DOUBLE_EQ(r->complete[0], 1.0);
    EXPECT_DOUBLE_EQ(r->accurate[1], 1.0);
    EXPECT_DOUBLE_EQ(r->median_rel_error, 0.0);
    EXPECT_DOUBLE_EQ(r->median_normal_error_deg, 0.0);
  }
}

TEST(EvaluateDepthMap, ScaledDepthMissesOnePercentButNotFive) {
  const GroundTruth gt;
  DenseMap depth = gt.depth;
  for (float& d : depth.data) d *= 1.03f;
  DenseMap normal = gt.normal;
  // Tilt every normal by 30 degrees.
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 8; ++c) {
      normal.At(r, c, 0) = 0.5f;
      normal.At(r, c, 2) = -std::sqrt(0.75f);
    }
  }
  const DepthMapMetrics m =
      EvaluateDepthMap(depth, normal, gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_DOUBLE_EQ(m.all.complete[0], 0.0);
  EXPECT_DOUBLE_EQ(m.all.complete[1], 1.0);
  EXPECT_NEAR(m.all.median_rel_error, 0.03, 1e-6);
  EXPECT_NEAR(m.all.median_normal_error_deg, 30.0, 1e-3);
}

TEST(EvaluateDepthMap, InvalidPixelsCountAgainstCompletenessOnly) {
  const GroundTruth gt;
  DenseMap depth = gt.depth;
  // Invalidate the whole textureless half: zeros and a NaN.
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 4; ++c) depth.At(r, c) = 0.0f;
  }
  depth.At(0, 0) = std::nanf("");
  const DepthMapMetrics m =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_DOUBLE_EQ(m.all.valid_fraction, 0.5);
  EXPECT_DOUBLE_EQ(m.all.complete[0], 0.5);
  EXPECT_DOUBLE_EQ(m.all.accurate[0], 1.0);
  EXPECT_DOUBLE_EQ(m.textureless.valid_fraction, 0.0);
  EXPECT_DOUBLE_EQ(m.textureless.complete[1], 0.0);
  EXPECT_DOUBLE_EQ(m.textured.valid_fraction, 1.0);
  EXPECT_DOUBLE_EQ(m.textured.complete[1], 1.0);
}

// Ground truth at 2.00-2.07 m: +3 cm is beyond 2 cm and within 5 cm
// (absolute) while within 5 % (relative) as well.
TEST(EvaluateDepthMap, AbsoluteThresholdsBesideRelativeOnes) {
  const GroundTruth gt;
  DenseMap depth = gt.depth;
  for (float& d : depth.data) d += 0.03f;
  depth.At(0, 0) = 0.0f;  // one pixel without a prediction
  const DepthMapMetrics m =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_DOUBLE_EQ(m.all.complete_abs[0], 0.0);
  EXPECT_DOUBLE_EQ(m.all.complete_abs[1], 47.0 / 48.0);
  EXPECT_DOUBLE_EQ(m.all.accurate_abs[1], 1.0);
  EXPECT_DOUBLE_EQ(m.all.complete[0], 0.0);
  EXPECT_DOUBLE_EQ(m.all.accurate[1], 1.0);
}

// Sensor ground truth: a pixel without a measurement (0) is counted neither
// as missed nor as accurate or wrong, whatever the prediction there.
TEST(EvaluateDepthMap, PixelsWithoutMeasurementCountNeitherWay) {
  GroundTruth gt;
  DenseMap depth = gt.depth;
  for (int c = 0; c < 8; ++c) {
    gt.depth.At(0, c) = 0.0f;  // unmeasured row
    depth.At(0, c) = 9.0f;     // a wrong prediction there
    depth.At(1, c) = 0.0f;     // no prediction on a measured row
  }
  const DepthMapMetrics m =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, DenseMap(), gt.masks, kThresholds);
  EXPECT_EQ(m.all.num_gt, 40);
  EXPECT_EQ(m.all.num_valid, 32);
  EXPECT_DOUBLE_EQ(m.all.accurate[0], 1.0);
  EXPECT_DOUBLE_EQ(m.all.accurate_abs[0], 1.0);
  EXPECT_DOUBLE_EQ(m.all.complete[1], 32.0 / 40.0);
  EXPECT_DOUBLE_EQ(m.all.median_normal_error_deg, 0.0);  // no ground-truth normals
}

TEST(EvaluateDepthMap, SmallerPredictionSamplesGroundTruthNearest) {
  const GroundTruth gt;
  // Half resolution: predicted pixel (r, c) sits at GT pixel (2r, 2c).
  DenseMap depth(4, 3, 1);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) depth.At(r, c) = gt.depth.At(2 * r, 2 * c);
  }
  const DepthMapMetrics m =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_EQ(m.width, 4);
  EXPECT_EQ(m.all.num_gt, 12);
  EXPECT_DOUBLE_EQ(m.all.median_rel_error, 0.0);
  EXPECT_EQ(m.textureless.num_gt, 6);
}

TEST(EvaluateDepthMap, EdgeRegionsFollowTheirMasks) {
  GroundTruth gt;
  gt.masks.near_edge = cv::Mat(6, 8, CV_8UC1, cv::Scalar(0));
  gt.masks.alike_edge = cv::Mat(6, 8, CV_8UC1, cv::Scalar(0));
  gt.masks.near_edge.colRange(3, 5).setTo(255);
  gt.masks.alike_edge.colRange(4, 5).setTo(255);
  DenseMap depth = gt.depth;
  for (int r = 0; r < 6; ++r) depth.At(r, 4) = 0.0f;
  const DepthMapMetrics m =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_EQ(m.near_edge.num_gt, 12);
  EXPECT_EQ(m.near_edge.num_valid, 6);
  EXPECT_DOUBLE_EQ(m.near_edge.complete[0], 0.5);
  EXPECT_EQ(m.alike_edge.num_gt, 6);
  EXPECT_EQ(m.alike_edge.num_valid, 0);
  EXPECT_DOUBLE_EQ(m.alike_edge.complete[0], 0.0);
  EXPECT_EQ(m.all.num_gt, 48);  // the edge regions take no pixel from the others
  EXPECT_EQ(m.textureless.num_gt + m.textured.num_gt, 48);
}

TEST(EvaluateDepthMap, EmptyEdgeMasksHoldNoPixel) {
  const GroundTruth gt;
  const DepthMapMetrics m =
      EvaluateDepthMap(gt.depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds);
  EXPECT_EQ(m.near_edge.num_gt, 0);
  EXPECT_EQ(m.alike_edge.num_gt, 0);
  EXPECT_DOUBLE_EQ(m.near_edge.complete[0], 0.0);
}

TEST(EvaluateDepthMap, MaskOfAnotherSizeIsAnError) {
  GroundTruth gt;
  gt.masks.near_edge = cv::Mat(3, 4, CV_8UC1, cv::Scalar(255));
  EXPECT_THROW(EvaluateDepthMap(gt.depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds),
               std::invalid_argument);
}

// Where the ground truth is empty (sky in an exact render), a depth is a made
// up surface: counted in `empty` only when 0 means "nothing there", never in
// the regions.
TEST(EvaluateDepthMap, DepthWhereTheGroundTruthIsEmptyIsCountedApart) {
  GroundTruth gt;
  for (int c = 0; c < gt.depth.width; ++c) gt.depth.At(0, c) = 0.0f;  // the top row: sky
  DenseMap depth = gt.depth;
  for (int c = 0; c < 3; ++c) depth.At(0, c) = 5.0f;  // three sky pixels filled
  const DepthMapMetrics empty =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds, true);
  EXPECT_EQ(empty.empty.num_empty, 8);
  EXPECT_EQ(empty.empty.num_with_depth, 3);
  EXPECT_DOUBLE_EQ(empty.empty.with_depth_fraction, 3.0 / 8.0);
  EXPECT_EQ(empty.all.num_gt, 40);
  EXPECT_DOUBLE_EQ(empty.all.accurate[0], 1.0);
  const DepthMapMetrics unmeasured =
      EvaluateDepthMap(depth, DenseMap(), gt.depth, gt.normal, gt.masks, kThresholds, false);
  EXPECT_EQ(unmeasured.empty.num_empty, 0);
  EXPECT_EQ(unmeasured.empty.num_with_depth, 0);
  EXPECT_EQ(unmeasured.all.num_gt, 40);
}

TEST(AverageMetrics, PoolsTheEmptyPixelsOfEveryImage) {
  DepthMapMetrics a, b;
  a.empty.num_empty = 100;
  a.empty.num_with_depth = 50;
  b.empty.num_empty = 300;
  b.empty.num_with_depth = 0;
  const DepthMapMetrics avg = AverageMetrics({a, b});
  EXPECT_EQ(avg.empty.num_empty, 400);
  EXPECT_DOUBLE_EQ(avg.empty.with_depth_fraction, 0.125);
}

TEST(AverageMetrics, MeansPerImageFigures) {
  DepthMapMetrics a, b;
  a.all.num_gt = 10;
  a.all.complete[0] = 1.0;
  b.all.complete[0] = 0.5;
  b.missing = true;
  const DepthMapMetrics avg = AverageMetrics({a, b});
  EXPECT_DOUBLE_EQ(avg.all.complete[0], 0.75);
}

TEST(AverageMetrics, ImagesWithoutARegionAreLeftOutOfItsMean) {
  // a has no alike-edge pixel, b has 10, c is missing (counts as zeros).
  DepthMapMetrics a, b, c;
  a.all.num_gt = b.all.num_gt = 100;
  a.all.complete[0] = 0.9;
  b.all.complete[0] = 0.6;
  b.alike_edge.num_gt = 10;
  b.alike_edge.complete[0] = 0.6;
  c.missing = true;
  const DepthMapMetrics avg = AverageMetrics({a, b, c});
  EXPECT_DOUBLE_EQ(avg.all.complete[0], 0.5);
  EXPECT_DOUBLE_EQ(avg.alike_edge.complete[0], 0.3);
  EXPECT_EQ(avg.alike_edge.num_gt, 10);
  EXPECT_EQ(AverageMetrics({a}).alike_edge.complete[0], 0.0);
}

}  // namespace
}  // namespace eval
}  // namespace msp

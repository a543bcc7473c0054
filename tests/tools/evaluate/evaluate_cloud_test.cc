#include "tools/evaluate/evaluate_cloud.h"

#include <gtest/gtest.h>

#include "tools/evaluate/point_grid.h"

namespace msp {
namespace eval {
namespace {

// A 1 m x 1 m planar grid with 1 cm spacing at z = 0.
std::vector<Eigen::Vector3f> PlaneGrid(float z = 0.0f) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i <= 100; ++i) {
    for (int j = 0; j <= 100; ++j) points.emplace_back(0.01f * i, 0.01f * j, z);
  }
  return points;
}

TEST(PointGrid, FindsNeighboursWithinRadiusOnly) {
  const std::vector<Eigen::Vector3f> points = {{0, 0, 0}, {1, 0, 0}};
  const PointGrid grid(points, 0.1);
  EXPECT_TRUE(grid.HasNeighbor({0.05f, 0.0f, 0.0f}));
  EXPECT_TRUE(grid.HasNeighbor({0.0f, 0.0999f, 0.0f}));
  EXPECT_TRUE(grid.HasNeighbor({0.95f, -0.02f, 0.0f}));
  EXPECT_FALSE(grid.HasNeighbor({0.5f, 0.0f, 0.0f}));
  EXPECT_FALSE(grid.HasNeighbor({0.08f, 0.08f, 0.0f}));  // 0.113 away
  EXPECT_FALSE(grid.HasNeighbor({-0.15f, 0.0f, 0.0f}));  // negative cells
}

TEST(EvaluateCloud, IdenticalSetsScorePerfectly) {
  const std::vector<Eigen::Vector3f> gt = PlaneGrid();
  const CloudMetrics m =
      EvaluateCloud(gt, {}, gt, {}, 3, 1.0, CloudThresholds(1.0, {0.005, 0.02}, {}));
  ASSERT_EQ(m.thresholds.size(), 2u);
  for (const CloudThresholdMetrics& t : m.thresholds) {
    EXPECT_DOUBLE_EQ(t.accuracy, 1.0);
    EXPECT_DOUBLE_EQ(t.completeness, 1.0);
    EXPECT_DOUBLE_EQ(t.completeness_multi, 1.0);
    EXPECT_DOUBLE_EQ(t.f1, 1.0);
  }
  EXPECT_DOUBLE_EQ(m.thresholds[0].metres, 0.005);
}

TEST(EvaluateCloud, ShiftBetweenThresholdsFailsOnlyTheSmallOne) {
  const std::vector<Eigen::Vector3f> gt = PlaneGrid();
  // 1 cm off the plane: beyond 0.5 cm, within 2 cm.
  const CloudMetrics m =
      EvaluateCloud(PlaneGrid(0.01f), {}, gt, {}, 3, 1.0, CloudThresholds(1.0, {0.005}, {0.02}));
  EXPECT_DOUBLE_EQ(m.thresholds[0].accuracy, 0.0);
  EXPECT_DOUBLE_EQ(m.thresholds[0].completeness, 0.0);
  EXPECT_DOUBLE_EQ(m.thresholds[0].f1, 0.0);
  EXPECT_DOUBLE_EQ(m.thresholds[1].accuracy, 1.0);
  EXPECT_DOUBLE_EQ(m.thresholds[1].completeness, 1.0);
  EXPECT_FALSE(m.thresholds[0].absolute);
  EXPECT_TRUE(m.thresholds[1].absolute);  // the absolute ones come after
  EXPECT_DOUBLE_EQ(m.thresholds[1].metres, 0.02);
  EXPECT_DOUBLE_EQ(m.thresholds[1].fraction, 0.02);
}

// Points the ground truth has no measurement for are left out of accuracy;
// completeness is over the samples and does not change.
TEST(EvaluateCloud, UnjudgedPointsCountNeitherWay) {
  const std::vector<Eigen::Vector3f> gt = PlaneGrid();
  std::vector<Eigen::Vector3f> points = gt;
  std::vector<uint8_t> judged(points.size(), 1);
  for (size_t i = 0; i < gt.size(); ++i) {
    points.push_back(gt[i] + Eigen::Vector3f(0, 0, 1));
    judged.push_back(i % 2 == 0 ? 0 : 1);  // half the outliers are judged
  }
  const CloudMetrics m =
      EvaluateCloud(points, judged, gt, {}, 3, 1.0, CloudThresholds(1.0, {}, {0.005}));
  const size_t judged_outliers = gt.size() / 2;  // odd indices
  EXPECT_EQ(m.num_points, static_cast<int>(2 * gt.size()));
  EXPECT_EQ(m.num_judged, static_cast<int>(gt.size() + judged_outliers));
  EXPECT_DOUBLE_EQ(m.thresholds[0].accuracy,
                   static_cast<double>(gt.size()) / (gt.size() + judged_outliers));
  EXPECT_DOUBLE_EQ(m.thresholds[0].completeness, 1.0);
}

TEST(EvaluateCloud, HalfCoverageAndOutliersGiveExpectedFigures) {
  const std::vector<Eigen::Vector3f> gt = PlaneGrid();
  // Reconstruction: the x < 0.5 half of the plane (51 of 101 columns) plus
  // as many outliers 1 m above it.
  std::vector<Eigen::Vector3f> points;
  for (const Eigen::Vector3f& p : gt) {
    if (p.x() < 0.505f) points.push_back(p);
  }
  const size_t inliers = points.size();
  for (size_t i = 0; i < inliers; ++i) points.push_back(points[i] + Eigen::Vector3f(0, 0, 1));
  const CloudMetrics m =
      EvaluateCloud(points, {}, gt, {}, 3, 1.0, CloudThresholds(1.0, {0.002}, {}));
  const CloudThresholdMetrics& t = m.thresholds[0];
  EXPECT_DOUBLE_EQ(t.accuracy, 0.5);
  EXPECT_NEAR(t.completeness, 51.0 / 101.0, 1e-12);
  EXPECT_NEAR(t.f1, F1Score(0.5, 51.0 / 101.0), 1e-12);
}

TEST(EvaluateCloud, MultiViewCompletenessIgnoresSamplesSeenByFewViews) {
  const std::vector<Eigen::Vector3f> gt = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  const std::vector<uint8_t> views = {2, 3, 5, 2};
  const std::vector<Eigen::Vector3f> points = {{1, 0, 0}, {2, 0, 0}};
  const CloudMetrics m =
      EvaluateCloud(points, {}, gt, views, 3, 10.0, CloudThresholds(10.0, {0.01}, {}));
  EXPECT_EQ(m.num_gt_multi, 2);
  EXPECT_DOUBLE_EQ(m.thresholds[0].completeness, 0.5);
  EXPECT_DOUBLE_EQ(m.thresholds[0].completeness_multi, 1.0);
  EXPECT_DOUBLE_EQ(m.thresholds[0].f1_multi, 1.0);
}

TEST(EvaluateCloud, EmptyReconstructionScoresZero) {
  const CloudMetrics m =
      EvaluateCloud({}, {}, PlaneGrid(), {}, 3, 1.0, CloudThresholds(1.0, {0.02}, {}));
  EXPECT_EQ(m.num_points, 0);
  EXPECT_DOUBLE_EQ(m.thresholds[0].accuracy, 0.0);
  EXPECT_DOUBLE_EQ(m.thresholds[0].completeness, 0.0);
  EXPECT_DOUBLE_EQ(m.thresholds[0].f1, 0.0);
}

}  // namespace
}  // namespace eval
}  // namespace msp

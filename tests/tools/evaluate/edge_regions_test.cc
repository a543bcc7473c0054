#include "tools/evaluate/edge_regions.h"

#include <gtest/gtest.h>

#include <string>

namespace msp {
namespace eval {
namespace {

constexpr int kWidth = 40;
constexpr int kHeight = 30;

// One row of `mask` as a bit string ("0011100...") for readable failures.
std::string Row(const cv::Mat& mask, int row) {
  std::string s;
  for (int c = 0; c < mask.cols; ++c) s += mask.at<uint8_t>(row, c) ? '1' : '0';
  return s;
}

// The columns [lo, hi] set, the rest clear.
std::string Columns(int lo, int hi) {
  std::string s(kWidth, '0');
  for (int c = lo; c <= hi; ++c) s[c] = '1';
  return s;
}

// Depth `left` on columns < 20, `right` from column 20 on.
DenseMap VerticalStep(float left, float right) {
  DenseMap depth(kWidth, kHeight, 1);
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) depth.At(r, c) = c < 20 ? left : right;
  }
  return depth;
}

cv::Mat TwoColours(const cv::Vec3b& left, const cv::Vec3b& right) {
  cv::Mat image(kHeight, kWidth, CV_8UC3);
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) image.at<cv::Vec3b>(r, c) = c < 20 ? left : right;
  }
  return image;
}

TEST(EdgeBandRadius, SpansTheBandInMapPixels) {
  EXPECT_EQ(EdgeBandRadius(640, 480, 640, 480), kEdgeBandPixels);
  EXPECT_EQ(EdgeBandRadius(640, 480, 320, 240), 2 * kEdgeBandPixels);
  EXPECT_EQ(EdgeBandRadius(640, 480, 321, 241), 2 * kEdgeBandPixels);  // rounded
  EXPECT_EQ(EdgeBandRadius(640, 480, 160, 120), 4 * kEdgeBandPixels);
  EXPECT_EQ(EdgeBandRadius(640, 480, 1280, 960), kEdgeBandPixels);  // never below the band
}

TEST(FindEdgeRegions, StepEdgeBandCoversBothSides) {
  const EdgeRegions regions =
      FindEdgeRegions(VerticalStep(2.0f, 3.0f), TwoColours({90, 90, 90}, {90, 90, 90}), 4);
  // Edge pixels in columns 19 and 20, widened by 4: columns 15..24.
  EXPECT_EQ(cv::countNonZero(regions.near_edge), 10 * kHeight);
  for (int r = 0; r < kHeight; ++r) ASSERT_EQ(Row(regions.near_edge, r), Columns(15, 24)) << r;
  EXPECT_EQ(cv::countNonZero(regions.alike_edge), 10 * kHeight);
}

TEST(FindEdgeRegions, SmallDepthChangeIsNoEdge) {
  // 2 % between neighbours: a slanted surface, not an edge.
  const EdgeRegions regions =
      FindEdgeRegions(VerticalStep(2.0f, 2.04f), TwoColours({90, 90, 90}, {90, 90, 90}), 4);
  EXPECT_EQ(cv::countNonZero(regions.near_edge), 0);
  EXPECT_EQ(cv::countNonZero(regions.alike_edge), 0);
}

TEST(FindEdgeRegions, BandRadiusSetsTheWidth) {
  const EdgeRegions regions =
      FindEdgeRegions(VerticalStep(2.0f, 3.0f), TwoColours({90, 90, 90}, {90, 90, 90}), 1);
  for (int r = 0; r < kHeight; ++r) ASSERT_EQ(Row(regions.near_edge, r), Columns(18, 21)) << r;
}

TEST(FindEdgeRegions, AlikeAndDistinctColoursAcrossTheEdge) {
  const DenseMap depth = VerticalStep(2.0f, 3.0f);
  // Either side of the threshold: |(4, 5, 6)| = 8.8 is alike, |(4, 6, 7)| =
  // 10.05 distinct.
  const EdgeRegions alike = FindEdgeRegions(depth, TwoColours({90, 90, 90}, {94, 95, 96}), 4);
  EXPECT_EQ(cv::countNonZero(alike.alike_edge), 10 * kHeight);
  const EdgeRegions distinct = FindEdgeRegions(depth, TwoColours({90, 90, 90}, {94, 96, 97}), 4);
  EXPECT_EQ(cv::countNonZero(distinct.near_edge), 10 * kHeight);
  EXPECT_EQ(cv::countNonZero(distinct.alike_edge), 0);
}

TEST(FindEdgeRegions, ThePixelsAtTheEdgeDoNotDecide) {
  // A camera pixel on an edge mixes both surfaces: a blend in columns 19 and
  // 20 leaves alike sides alike, and does not make distinct sides alike.
  const DenseMap depth = VerticalStep(2.0f, 3.0f);
  cv::Mat alike = TwoColours({90, 90, 90}, {90, 90, 90});
  cv::Mat distinct = TwoColours({40, 40, 200}, {200, 40, 40});
  for (int r = 0; r < kHeight; ++r) {
    alike.at<cv::Vec3b>(r, 19) = alike.at<cv::Vec3b>(r, 20) = {20, 200, 20};
    distinct.at<cv::Vec3b>(r, 19) = distinct.at<cv::Vec3b>(r, 20) = {120, 40, 120};
  }
  EXPECT_EQ(cv::countNonZero(FindEdgeRegions(depth, alike, 4).alike_edge), 10 * kHeight);
  EXPECT_EQ(cv::countNonZero(FindEdgeRegions(depth, distinct, 4).alike_edge), 0);
}

TEST(FindEdgeRegions, EachEdgeIsJudgedByItsOwnSides) {
  // A (columns < 20) grey at depth 2; B (right, rows < 15) the same grey at
  // depth 3; C (right, rows >= 15) red at depth 4. Only the A|B edge is alike.
  DenseMap depth(kWidth, kHeight, 1);
  cv::Mat image(kHeight, kWidth, CV_8UC3);
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) {
      const bool a = c < 20, b = !a && r < 15;
      depth.At(r, c) = a ? 2.0f : (b ? 3.0f : 4.0f);
      image.at<cv::Vec3b>(r, c) = (a || b) ? cv::Vec3b(100, 100, 100) : cv::Vec3b(30, 30, 220);
    }
  }
  const EdgeRegions regions = FindEdgeRegions(depth, image, 4);
  // Near edge: the vertical edge's band (columns 15..24) plus the B|C edge's
  // (rows 10..19, columns from 20 - 4 = 16 on).
  for (int r = 0; r < kHeight; ++r) {
    const bool horizontal_band = r >= 10 && r <= 19;
    ASSERT_EQ(Row(regions.near_edge, r), horizontal_band ? Columns(15, 39) : Columns(15, 24)) << r;
  }
  // Alike: the A|B pairs (rows 0..14) widened by 4, rows 0..18.
  for (int r = 0; r < kHeight; ++r) {
    ASSERT_EQ(Row(regions.alike_edge, r), r <= 18 ? Columns(15, 24) : std::string(kWidth, '0'))
        << r;
  }
}

TEST(FindEdgeRegions, ASideWithoutSamplesLeavesTheEdgeUnclassified) {
  // A one-pixel-wide post (column 10) in front: beyond its pixel there is no
  // sample of its surface, so its alike colour cannot be told from a blend.
  DenseMap depth(kWidth, kHeight, 1, 3.0f);
  for (int r = 0; r < kHeight; ++r) depth.At(r, 10) = 2.0f;
  const EdgeRegions regions = FindEdgeRegions(depth, TwoColours({90, 90, 90}, {90, 90, 90}), 2);
  for (int r = 0; r < kHeight; ++r) ASSERT_EQ(Row(regions.near_edge, r), Columns(7, 13)) << r;
  EXPECT_EQ(cv::countNonZero(regions.alike_edge), 0);
}

TEST(FindEdgeRegions, PixelsWithoutDepthAreNeitherEdgeNorBand) {
  DenseMap depth = VerticalStep(2.0f, 3.0f);
  // A hole (no ground truth) inside the band, and one at the far left next to
  // valid depths: a missing depth makes no edge.
  depth.At(5, 17) = 0.0f;
  for (int r = 0; r < kHeight; ++r) depth.At(r, 0) = 0.0f;
  const EdgeRegions regions = FindEdgeRegions(depth, TwoColours({90, 90, 90}, {90, 90, 90}), 4);
  EXPECT_EQ(regions.near_edge.at<uint8_t>(5, 17), 0);
  EXPECT_EQ(cv::countNonZero(regions.near_edge), 10 * kHeight - 1);
}

}  // namespace
}  // namespace eval
}  // namespace msp

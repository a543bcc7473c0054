#include "prior/segmentation_prior.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "tests/support/prior_anchors.h"

namespace msp {
namespace {

constexpr core::PlaneRansacParams kRansac{/*inlier_distance=*/0.01f, /*iterations=*/50};

std::vector<uint8_t> Bits(const std::vector<std::string>& rows) {
  std::vector<uint8_t> out;
  for (const std::string& row : rows) {
    for (char c : row) out.push_back(c == '1');
  }
  return out;
}

TEST(SegmentationPrior, BoundaryMapMarksBothSidesOfEveryLabelChange) {
  const std::vector<int32_t> labels = {1, 1, 2, 2, 2,  //
                                       1, 1, 2, 2, 2,  //
                                       3, 3, 3, 2, 2,  //
                                       3, 3, 3, 3, 3};
  EXPECT_EQ(ComputeBoundaryMap(labels, 5, 4), Bits({"01100", "11100", "11111", "00011"}));
  EXPECT_EQ(ComputeBoundaryMap(std::vector<int32_t>(12, 7), 4, 3), std::vector<uint8_t>(12, 0));
  // Unlabelled (0) is a label like any other for the boundary.
  EXPECT_EQ(ComputeBoundaryMap({0, 0, 5}, 3, 1), Bits({"011"}));
}

TEST(SegmentationPrior, UnionOfLayersHasTheUnionOfTheBoundaries) {
  LabelLayers layers;
  layers.width = 4;
  layers.height = 3;
  layers.levels = {{1, 1, 2, 2, 1, 1, 2, 2, 1, 1, 2, 2},   // vertical split
                   {4, 4, 4, 4, 4, 4, 4, 4, 6, 6, 6, 6}};  // horizontal split
  const Segmentation seg = UnionOfLayers(layers);
  EXPECT_EQ(seg.edges, UnionBoundaryMap(ComputeBoundaryMaps(layers)));
  EXPECT_EQ(seg.edges, Bits({"0110", "1111", "1111"}));
  // Four quadrant regions.
  EXPECT_NE(seg.labels[0], seg.labels[3]);
  EXPECT_NE(seg.labels[0], seg.labels[8]);
  EXPECT_NE(seg.labels[3], seg.labels[11]);
  EXPECT_EQ(seg.labels[0], seg.labels[5]);
}

TEST(SegmentationPrior, RegionIsKeptInTheLayerMostOfItsPixelsChose) {
  // 4x2: level 0 one region, level 1 split into left (1) and right (2).
  LabelLayers layers;
  layers.width = 4;
  layers.height = 2;
  layers.levels = {{9, 9, 9, 9, 9, 9, 9, 9}, {1, 1, 2, 2, 1, 1, 2, 2}};
  // Left pixels: three choose layer 1, one chooses both (a tie); right: none.
  const std::vector<uint32_t> best = {0b10, 0b10, 0, 0, 0b11, 0b10, 0, 0};
  const std::vector<std::vector<uint8_t>> kept = RetainRegions(layers, best);
  // Level 0's region: votes l0 = 1, l1 = 4 -> dropped. Level 1 left: kept;
  // level 1 right: no votes -> the tie goes to level 0 -> dropped.
  EXPECT_EQ(kept[0], std::vector<uint8_t>(8, 0));
  EXPECT_EQ(kept[1], (std::vector<uint8_t>{1, 1, 0, 0, 1, 1, 0, 0}));
  const Segmentation seg = AggregateRegions(layers, kept);
  EXPECT_EQ(seg.edges, Bits({"0110", "0110"}));
}

TEST(SegmentationPrior, CoarseRegionKeptWhereItsPixelsPreferIt) {
  LabelLayers layers;
  layers.width = 4;
  layers.height = 1;
  layers.levels = {{3, 3, 3, 0}, {1, 2, 2, 2}};
  const std::vector<uint32_t> best = {0b01, 0b01, 0b10, 0b01};
  const std::vector<std::vector<uint8_t>> kept = RetainRegions(layers, best);
  // Level 0 region 3: votes l0 = 2, l1 = 1 -> kept; unlabelled 0 never kept.
  EXPECT_EQ(kept[0], (std::vector<uint8_t>{1, 1, 1, 0}));
  // Level 1 region 1: l0 = 1 -> dropped; region 2: l0 = 2, l1 = 1 -> dropped.
  EXPECT_EQ(kept[1], (std::vector<uint8_t>{0, 0, 0, 0}));
  EXPECT_EQ(AggregateRegions(layers, kept).edges, Bits({"0011"}));
}

// Anchors of pixel p: those left of a depth edge between columns 11 and 12
// lie on the plane z = 2, the others on the plane z = 5 + 0.3 x + 0.2 y.
core::PriorAnchors AnchorsAround(int col, int row) {
  return test::AnchorsAcrossDepthEdge(col, row, {2, 4, 6, 8, 3, 14, 16, 18, 20, 15},
                                      {2, 5, 9, 14, 18, 3, 7, 11, 16, 19}, /*edge_col=*/12,
                                      [](float x, float y) { return 5.0f + 0.3f * x + 0.2f * y; });
}

TEST(SegmentationPrior, AggregationKeepsTheLayerThatFollowsTheDepthEdge) {
  constexpr int kSize = 22;
  LabelLayers layers;
  layers.width = kSize;
  layers.height = kSize;
  // Level 0: one region. Level 1: split on the depth edge. Level 2: split on
  // the edge and again across p's own surface (rows < 10 / >= 10).
  std::vector<int32_t> level0(kSize * kSize, 1), level1(kSize * kSize), level2(kSize * kSize);
  for (int row = 0; row < kSize; ++row) {
    for (int col = 0; col < kSize; ++col) {
      level1[row * kSize + col] = col < 12 ? 1 : 2;
      level2[row * kSize + col] = (col < 12 ? 1 : 3) + (row < 10 ? 0 : 1);
    }
  }
  layers.levels = {level0, level1, level2};
  const std::vector<std::vector<uint8_t>> boundaries = ComputeBoundaryMaps(layers);
  std::vector<core::PriorAnchors> pixels = {AnchorsAround(5, 4), AnchorsAround(7, 16),
                                            AnchorsAround(17, 5), AnchorsAround(16, 17)};
  BestLayerOptions options;
  options.ransac = kRansac;
  const std::vector<uint32_t> best = ChooseBestLayers(layers, boundaries, pixels, options);
  for (const core::PriorAnchors& p : pixels) {
    EXPECT_EQ(best[p.row * kSize + p.col], 0b010u) << "pixel " << p.col << "," << p.row;
  }
  EXPECT_EQ(best[0], 0u);  // not an unreliable pixel

  const std::vector<std::vector<uint8_t>> kept = RetainRegions(layers, best);
  const Segmentation seg = AggregateRegions(layers, kept);
  EXPECT_EQ(seg.edges, boundaries[1]);
}

TEST(SegmentationPrior, ChooseBestLayersIsDeterministicAcrossThreadCounts) {
  constexpr int kSize = 22;
  LabelLayers layers;
  layers.width = layers.height = kSize;
  std::vector<int32_t> split(kSize * kSize);
  for (int i = 0; i < kSize * kSize; ++i) split[i] = (i % kSize) < 12 ? 1 : 2;
  layers.levels = {std::vector<int32_t>(kSize * kSize, 1), split};
  std::vector<core::PriorAnchors> pixels;
  for (int row = 1; row < kSize - 1; row += 3) {
    for (int col = 1; col < kSize - 1; col += 2) pixels.push_back(AnchorsAround(col, row));
  }
  BestLayerOptions options;
  options.ransac = core::PlaneRansacParams{0.01f, 10};  // sampled, not exhaustive
  options.num_threads = 1;
  const std::vector<uint32_t> one =
      ChooseBestLayers(layers, ComputeBoundaryMaps(layers), pixels, options);
  options.num_threads = 2;
  EXPECT_EQ(one, ChooseBestLayers(layers, ComputeBoundaryMaps(layers), pixels, options));
}

}  // namespace
}  // namespace msp

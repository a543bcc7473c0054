#include "core/prior/best_layer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tests/support/images.h"
#include "tests/support/prior_anchors.h"

namespace msp {
namespace core {
namespace {

constexpr PlaneRansacParams kRansac{/*inlier_distance=*/0.01f, /*iterations=*/50};
constexpr uint64_t kKey = 1234;

// Anchors of pixel p = (10, 10) at the given pixels; those with col < 10 lie
// on the plane z = 2 (the surface of p), the others on z = 5 + 0.3 x (behind
// a depth edge at column 10), so only anchors left of the edge are inliers
// of the right plane.
PriorAnchors MakeAnchors(const std::vector<int>& cols, const std::vector<int>& rows) {
  return test::AnchorsAcrossDepthEdge(10, 10, cols, rows, /*edge_col=*/10, [](float x, float y) {
    return 5.0f + 0.3f * x + 0.7f * y * y;
  });
}

TEST(BestLayer, PlaneInliersOfPointsOnAPlaneWithOutliers) {
  Vec3 points[kMaxPriorAnchors];
  for (int i = 0; i < 20; ++i) points[i] = Vec3{0.1f * (i % 5), 0.1f * (i / 5), 1.0f};
  for (int i = 20; i < 26; ++i) points[i] = Vec3{0.05f * i, 0.3f, 1.5f + 0.1f * i};
  const uint32_t all = (1u << 26) - 1u;
  // C(26, 3) > 50: sampled triangles; the plane with 20 points is found.
  EXPECT_EQ(SubsetPlaneInliers(points, all, kRansac, MakeRng(kKey)), 20);
  EXPECT_EQ(SubsetPlaneInliers(points, 0b100011u, kRansac, MakeRng(kKey)), 3);
  EXPECT_EQ(SubsetPlaneInliers(points, 0b11u, kRansac, MakeRng(kKey)), 0);  // too few
  // Collinear points span no plane.
  Vec3 line[kMaxPriorAnchors];
  for (int i = 0; i < 4; ++i) line[i] = Vec3{0.1f * i, 0.0f, 1.0f};
  EXPECT_EQ(SubsetPlaneInliers(line, 0b1111u, kRansac, MakeRng(kKey)), 0);
}

TEST(BestLayer, MoreInliersWinThenHigherRatio) {
  // 6 anchors on p's surface (cols < 10) and 3 behind the edge.
  const PriorAnchors a =
      MakeAnchors({2, 4, 6, 8, 3, 5, 14, 16, 18}, {2, 4, 6, 8, 15, 12, 3, 9, 15});
  const uint32_t left = 0b000111111u;
  const uint32_t all = 0b111111111u;
  const uint32_t some_left = 0b000001111u;
  // A_0 = 6 of 9, A_1 = 6 of 6, A_2 = 4 of 4: layer 1 wins (same A, higher ratio).
  uint32_t subsets[3] = {all, left, some_left};
  EXPECT_EQ(BestLayers(a, subsets, 3, kRansac, MakeRng(kKey)), 0b010u);
  // More inliers beat a higher ratio.
  uint32_t subsets2[2] = {some_left, all};
  EXPECT_EQ(BestLayers(a, subsets2, 2, kRansac, MakeRng(kKey)), 0b10u);
  // Identical subsets tie: both layers are best.
  uint32_t subsets3[3] = {left, some_left, left};
  EXPECT_EQ(BestLayers(a, subsets3, 3, kRansac, MakeRng(kKey)), 0b101u);
  // Nothing to planarise.
  uint32_t subsets4[2] = {0u, 0b11u};
  EXPECT_EQ(BestLayers(a, subsets4, 2, kRansac, MakeRng(kKey)), 0u);
}

TEST(BestLayer, LayerWhoseBoundaryFollowsTheDepthEdgeIsChosen) {
  constexpr int kSize = 24;
  // Layer 0: no boundary. Layer 1: boundary on the depth edge (columns 10-11,
  // p at column 10 sits on it). Layer 2: a wrong boundary at rows 6-7 that
  // cuts p's own surface in half.
  const test::EdgeMap none = test::NoEdges(kSize, kSize);
  const test::EdgeMap right = test::VerticalEdge(kSize, kSize, 10);
  test::EdgeMap wrong = test::NoEdges(kSize, kSize);
  for (int i = 0; i < kSize; ++i) wrong.bits[6 * kSize + i] = wrong.bits[7 * kSize + i] = 1;
  // p is at (10, 10) on the edge pixel of its own (left) region.
  PriorAnchors a = MakeAnchors({2, 4, 6, 8, 3, 5, 14, 16, 18}, {2, 4, 6, 8, 15, 12, 3, 9, 15});
  std::vector<uint32_t> packed(kSize * kSize);
  for (int i = 0; i < kSize * kSize; ++i)
    packed[i] = none.bits[i] | right.bits[i] << 1 | wrong.bits[i] << 2;
  const LayerBoundaryView views{packed.data(), kSize, kSize, kSize};
  EXPECT_EQ(BestLayersForPixel(a, views, 3, kRansac, MakeRng(kKey)), 0b010u);
}

}  // namespace
}  // namespace core
}  // namespace msp

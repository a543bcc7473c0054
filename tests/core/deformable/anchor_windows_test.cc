#include "core/deformable/anchor_windows.h"

#include <gtest/gtest.h>

#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

using test::Image;

constexpr int kW = 64, kH = 48;
const NccParams kAnchorNcc{5, 5, 0, 5.0f, 0.2f};  // APD's 3x3 anchor windows

// Anchors inside, over the reference border, and near the right edge where
// a shifted warp leaves the source.
const int kCols[kMaxAnchors] = {20, 30, 2, 40, 57, 12, 33, 50};
const int kRows[kMaxAnchors] = {20, 25, 20, 40, 10, 8, 30, 44};

TEST(AnchorWindows, CostSumEqualsTheGeneralCostOfEachAnchor) {
  const Image ref = test::NoiseImage(kW, kH, 1), src = test::NoiseImage(kW, kH, 2);
  for (int count : {8, 5, 1}) {
    AnchorWindows w;
    PrepareAnchorWindows(ref.View(), kCols, kRows, count, 5, 5, &w);
    EXPECT_EQ(w.num_samples, 9);
    EXPECT_EQ((w.fast >> 2) & 1u, 0u);  // anchor 2 is 2 px from the border
    for (const Mat3& H :
         {test::MildWarp(0.4f, 0.3f), test::MildWarp(2.5f, -1.5f), test::MildWarp(-3.0f, 2.0f)}) {
      for (const Image* s : {&src, &ref}) {
        float expected = 0.0f;
        for (int a = 0; a < count; ++a) {
          expected += GeneralNccCost(ref.View(), s->View(), H, kCols[a], kRows[a], kAnchorNcc);
        }
        EXPECT_NEAR(AnchorCostSum(w, ref.View(), s->View(), H, kAnchorNcc), expected, 1e-4f);
      }
    }
  }
}

TEST(AnchorWindows, ScalarAndVectorSumsAgree) {
  const Image ref = test::NoiseImage(kW, kH, 3), src = test::NoiseImage(kW, kH, 4);
  AnchorWindows w;
  PrepareAnchorWindows(ref.View(), kCols, kRows, kMaxAnchors, 5, 5, &w);
  AnchorSums scalar, vector;
  AnchorSumsScalar(w, src.View(), test::MildWarp(2.5f, -1.5f), &scalar);
  AnchorSumsOf(w, src.View(), test::MildWarp(2.5f, -1.5f), &vector);
  EXPECT_EQ(scalar.inside, vector.inside);
  EXPECT_NE(scalar.inside, 0u);
  EXPECT_NE(scalar.inside, 0xFFu);  // some windows left the source or the reference
  // Anchor 4's right column leaves the source: its sums cover the other 6 samples.
  EXPECT_EQ((scalar.inside >> 4) & 1u, 0u);
  EXPECT_EQ(scalar.count[4], 6.0f);
  for (int a = 0; a < kMaxAnchors; ++a) {
    if (!((w.fast >> a) & 1u)) continue;
    EXPECT_EQ(scalar.count[a], vector.count[a]);
    EXPECT_NEAR(scalar.s[a], vector.s[a], 1e-4f);
    EXPECT_NEAR(scalar.ss[a], vector.ss[a], 1e-4f);
    EXPECT_NEAR(scalar.rs[a], vector.rs[a], 1e-5f);
    EXPECT_NEAR(scalar.r[a], vector.r[a], 1e-5f);
    EXPECT_NEAR(scalar.rr[a], vector.rr[a], 1e-5f);
  }
}

// A window that leaves the source in part is scored on its valid samples, as
// GeneralNccCost scores it: here 6 of 9, enough for a real cost.
TEST(AnchorWindows, PartialWindowCostsAsTheGeneralCost) {
  const Image ref = test::NoiseImage(kW, kH, 5), src = test::NoiseImage(kW, kH, 6);
  const int col[1] = {57}, row[1] = {10};
  AnchorWindows w;
  PrepareAnchorWindows(ref.View(), col, row, 1, 5, 5, &w);
  ASSERT_EQ(w.fast, 1u);
  const Mat3 H = test::MildWarp(2.5f, -1.5f);
  AnchorSums sums;
  AnchorSumsOf(w, src.View(), H, &sums);
  EXPECT_EQ(sums.inside, 0u);
  const float expected = GeneralNccCost(ref.View(), src.View(), H, col[0], row[0], kAnchorNcc);
  EXPECT_LT(expected, kMaxCost);
  EXPECT_NEAR(AnchorCostSum(w, ref.View(), src.View(), H, kAnchorNcc), expected, 1e-5f);
}

TEST(AnchorWindows, FlatAnchorWindowCostsMax) {
  const Image flat = test::FlatImage(kW, kH, 0.3f), src = test::NoiseImage(kW, kH, 4);
  AnchorWindows w;
  PrepareAnchorWindows(flat.View(), kCols, kRows, 1, 5, 5, &w);
  EXPECT_EQ(w.textured, 0u);
  EXPECT_EQ(AnchorCostSum(w, flat.View(), src.View(), test::MildWarp(0.4f, 0.3f), kAnchorNcc),
            kMaxCost);
}

// Pairs of (plane, anchor window) in the lanes of one batch cost what the
// general NCC gives each window under its own homography, and a pair's cost
// does not depend on its lane or on the pairs beside it: the bits are equal.
TEST(AnchorWindows, PairLanesCostWhatEachPairCostsAlone) {
  const Image ref = test::NoiseImage(kW, kH, 7), src = test::NoiseImage(kW, kH, 8);
  AnchorWindows w;
  PrepareAnchorWindows(ref.View(), kCols, kRows, kMaxAnchors, 5, 5, &w);
  // H = KRK - Kt m^T: test::MildWarp(0.4, 0.3) moved by each plane's m.
  RelativePose rel{};
  rel.KRK = test::MildWarp(0.4f, 0.3f);
  rel.Kt = Vec3{2.0f, -1.0f, 0.001f};
  PlaneWarp warps[kWindowLanes];
  for (int l = 0; l < kWindowLanes; ++l) {
    warps[l] = PlaneWarp{{0.002f * (l - 3), -0.001f * l, 0.4f * l - 1.0f}};
  }
  // Lanes mix anchors (the border anchor 2, the partial anchor 4, a repeat).
  const int anchors[kWindowLanes] = {4, 0, 2, 7, 1, 4, 6, 3};
  AnchorPairLanes lanes;
  PrepareAnchorPairLanes(w, anchors, warps, kWindowLanes, &lanes);
  float costs[kWindowLanes];
  AnchorPairCosts(w, lanes, rel, ref.View(), src.View(), kAnchorNcc, costs);
  for (int l = 0; l < kWindowLanes; ++l) {
    const Mat3 H = WarpHomography(rel, warps[l]);
    const int a = anchors[l];
    EXPECT_NEAR(costs[l], GeneralNccCost(ref.View(), src.View(), H, kCols[a], kRows[a], kAnchorNcc),
                1e-4f)
        << "lane " << l;
  }
  EXPECT_NE(costs[0], costs[5]);  // anchor 4 under two planes
  // Each pair alone in a batch of one, in the last lane of a batch of 7.
  for (int l = 0; l < kWindowLanes; ++l) {
    AnchorPairLanes one;
    PrepareAnchorPairLanes(w, anchors + l, warps + l, 1, &one);
    float alone;
    AnchorPairCosts(w, one, rel, ref.View(), src.View(), kAnchorNcc, &alone);
    EXPECT_EQ(alone, costs[l]) << "lane " << l;
    int moved_anchors[7];
    PlaneWarp moved_warps[7];
    for (int i = 0; i < 7; ++i) {
      moved_anchors[i] = anchors[(l + 1 + i) % kWindowLanes];
      moved_warps[i] = warps[(l + 1 + i) % kWindowLanes];
    }
    moved_anchors[6] = anchors[l];
    moved_warps[6] = warps[l];
    AnchorPairLanes moved;
    PrepareAnchorPairLanes(w, moved_anchors, moved_warps, 7, &moved);
    float moved_costs[kWindowLanes];
    AnchorPairCosts(w, moved, rel, ref.View(), src.View(), kAnchorNcc, moved_costs);
    EXPECT_EQ(moved_costs[6], costs[l]) << "lane " << l;
  }
}

}  // namespace
}  // namespace core
}  // namespace msp

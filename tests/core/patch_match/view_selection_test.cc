#include "core/patch_match/view_selection.h"

#include <gtest/gtest.h>

namespace msp {
namespace core {
namespace {

constexpr int kViews = 4;

TEST(ViewSelection, GoodViewsAreDrawnAndBadViewsNever) {
  // Views 0 and 2 match every candidate well; view 1 mismatches (cost 1.9),
  // view 3 matches only two candidates.
  float costs[8 * kViews];
  for (int k = 0; k < 8; ++k) {
    costs[k * kViews + 0] = 0.1f;
    costs[k * kViews + 1] = 1.9f;
    costs[k * kViews + 2] = 0.2f;
    costs[k * kViews + 3] = k < 2 ? 0.1f : 1.0f;
  }
  Rng rng = MakeRng(RngKey(0, 0, 0, 0, 0));
  float weights[kViews];
  const uint32_t mask = SelectViews(costs, 8, kViews, kViews, 0, 0u, 15, &rng, weights);
  EXPECT_TRUE(mask & 1u);
  EXPECT_TRUE(mask & 4u);
  EXPECT_FALSE(mask & 2u);
  EXPECT_EQ(weights[1], 0.0f);
  EXPECT_NEAR(weights[0] + weights[1] + weights[2] + weights[3], 1.0f, 1e-6f);
}

TEST(ViewSelection, DrawsFollowTheLikelihoods) {
  // Views 0-2 match every candidate alike, so their likelihoods are the
  // priors: 0.9 for the views selected last time (0 and 2), 0.1 for view 1.
  // View 3, last, mismatches: likelihood 0, never drawn.
  float costs[8 * kViews];
  for (int k = 0; k < 8; ++k) {
    for (int j = 0; j < 3; ++j) costs[k * kViews + j] = 0.1f;
    costs[k * kViews + 3] = 1.9f;
  }
  Rng rng = MakeRng(RngKey(7, 0, 0, 0, 0));
  float weights[kViews];
  const uint32_t mask = SelectViews(costs, 8, kViews, kViews, 0, 0x5u, 20000, &rng, weights);
  EXPECT_EQ(mask, 0x7u);
  EXPECT_NEAR(weights[0], 0.9f / 1.9f, 0.02f);
  EXPECT_NEAR(weights[1], 0.1f / 1.9f, 0.01f);
  EXPECT_NEAR(weights[2], 0.9f / 1.9f, 0.02f);
  EXPECT_EQ(weights[3], 0.0f);
}

TEST(ViewSelection, AllViewsBadFallsBackToEqualWeights) {
  float costs[8 * kViews];
  for (float& c : costs) c = 1.9f;
  Rng rng = MakeRng(1);
  float weights[kViews];
  const uint32_t mask = SelectViews(costs, 8, kViews, kViews, 0, 0u, 15, &rng, weights);
  EXPECT_EQ(mask, 0xFu);
  for (float w : weights) EXPECT_FLOAT_EQ(w, 0.25f);
}

TEST(ViewSelection, ThresholdDecaysWithIterations) {
  EXPECT_FLOAT_EQ(GoodCostThreshold(0), 0.8f);
  EXPECT_LT(GoodCostThreshold(3), GoodCostThreshold(1));
}

TEST(ViewSelection, AggregateIsWeightedMean) {
  const float costs[3] = {0.2f, 1.0f, 0.6f};
  const float weights[3] = {0.5f, 0.0f, 0.5f};
  EXPECT_FLOAT_EQ(AggregateCost(costs, weights, 3), 0.4f);
}

}  // namespace
}  // namespace core
}  // namespace msp

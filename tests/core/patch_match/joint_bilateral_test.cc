#include "core/patch_match/joint_bilateral.h"

#include <gtest/gtest.h>

namespace msp {
namespace core {
namespace {

TEST(JointBilateral, WeightFallsWithDistanceAndGuideDifference) {
  EXPECT_FLOAT_EQ(JointBilateralWeight(0.0f, 0.0f, 0.0f), 1.0f);
  EXPECT_LT(JointBilateralWeight(2.5f, 0.5f, 0.0f), JointBilateralWeight(1.5f, 0.5f, 0.0f));
  EXPECT_LT(JointBilateralWeight(0.5f, 0.5f, 0.3f), JointBilateralWeight(0.5f, 0.5f, 0.1f));
  EXPECT_FLOAT_EQ(JointBilateralWeight(-1.5f, 0.5f, -0.2f),
                  JointBilateralWeight(1.5f, -0.5f, 0.2f));
}

// The group of agreeing depths outweighs the single heaviest candidate, and
// the winner is a candidate's own depth, not a blend.
TEST(JointBilateral, ModeTakesTheHeaviestSurface) {
  const float depth[] = {2.0f, 3.0f, 3.02f, 2.97f};
  const float weight[] = {0.9f, 0.4f, 0.3f, 0.3f};
  EXPECT_EQ(WeightedDepthMode(depth, weight, 4), 1);  // 3.0 agrees with 3.02 and 2.97
  const float heavier[] = {1.1f, 0.4f, 0.3f, 0.3f};
  EXPECT_EQ(WeightedDepthMode(depth, heavier, 4), 0);
}

TEST(JointBilateral, ModeTiesGoToTheEarlierCandidate) {
  const float depth[] = {3.0f, 2.0f, 2.0f, 3.0f};
  const float weight[] = {0.5f, 0.5f, 0.5f, 0.5f};
  EXPECT_EQ(WeightedDepthMode(depth, weight, 4), 0);
  EXPECT_EQ(WeightedDepthMode(depth + 1, weight, 3), 0);
  const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};  // every weight underflowed
  EXPECT_EQ(WeightedDepthMode(depth, zero, 4), 0);
  EXPECT_EQ(WeightedDepthMode(depth, weight, 0), -1);
}

}  // namespace
}  // namespace core
}  // namespace msp

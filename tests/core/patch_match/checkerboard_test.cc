#include "core/patch_match/checkerboard.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <utility>

namespace msp {
namespace core {
namespace {

TEST(Checkerboard, RegionsHoldOnlyOppositeColourPixels) {
  std::set<std::pair<int, int>> all;
  for (int region = 0; region < kNumRegions; ++region) {
    for (int i = 0; i < RegionSize(region); ++i) {
      int dx, dy;
      RegionOffset(region, i, &dx, &dy);
      EXPECT_EQ(std::abs(dx + dy) % 2, 1) << region << " " << i;
      EXPECT_TRUE(all.insert({dx, dy}).second) << "duplicate offset " << dx << "," << dy;
    }
  }
  EXPECT_EQ(all.size(), 4u * kNearSamples + 4u * kFarSamples);
}

TEST(Checkerboard, FarStripsReachTwentyThreePixels) {
  int dx, dy;
  RegionOffset(4, kFarSamples - 1, &dx, &dy);  // up strip, last sample
  EXPECT_EQ(dx, 0);
  EXPECT_EQ(dy, -23);
  RegionOffset(7, 0, &dx, &dy);  // right strip, first sample
  EXPECT_EQ(dx, 3);
  EXPECT_EQ(dy, 0);
}

}  // namespace
}  // namespace core
}  // namespace msp

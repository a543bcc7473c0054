#include "patch_match/pixel_state_io.h"

#include <gtest/gtest.h>

#include <string>

namespace msp {
namespace {

PixelState NumberedState(int width, int height, bool with_planes) {
  PixelState state(width, height);
  for (size_t i = 0; i < state.depth.size(); ++i) {
    state.depth[i] = 1.0f + 0.001f * i;
    state.cost[i] = 0.5f / (1 + i);
    state.mask[i] = static_cast<uint32_t>(i * 2654435761u);
  }
  for (size_t i = 0; i < state.normal.size(); ++i) state.normal[i] = -0.25f * i;
  if (with_planes) {
    state.edges.assign(state.depth.size(), 5);
    state.classes.assign(state.depth.size(), 2);
    state.edges[1] = 0;
  }
  return state;
}

void ExpectEqual(const PixelState& a, const PixelState& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_EQ(a.mask, b.mask);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.classes, b.classes);
}

TEST(PixelStateIo, RoundTripsEveryPlaneBitForBit) {
  for (bool with_planes : {false, true}) {
    const PixelState state = NumberedState(7, 5, with_planes);
    PixelState back;
    ASSERT_TRUE(DeserializePixelState(SerializePixelState(state), &back));
    ExpectEqual(state, back);
  }
}

TEST(PixelStateIo, RefusesTruncatedLongerAndForeignBytes) {
  const std::string bytes = SerializePixelState(NumberedState(4, 3, true));
  PixelState back;
  EXPECT_FALSE(DeserializePixelState(bytes.substr(0, bytes.size() - 1), &back));
  EXPECT_FALSE(DeserializePixelState(bytes + "x", &back));
  EXPECT_FALSE(DeserializePixelState("", &back));
  std::string foreign = bytes;
  foreign[0] = 'X';
  EXPECT_FALSE(DeserializePixelState(foreign, &back));
}

}  // namespace
}  // namespace msp

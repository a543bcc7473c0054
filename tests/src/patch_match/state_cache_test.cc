#include "patch_match/state_cache.h"

#include <gtest/gtest.h>

#include <string>

#include "tests/support/temp_dir.h"

namespace msp {
namespace {

PixelState Filled(int w, int h, float value) {
  PixelState s(w, h);
  for (size_t i = 0; i < s.depth.size(); ++i) s.depth[i] = value + static_cast<float>(i);
  s.mask[0] = 5u;
  return s;
}

TEST(StateCache, SpillsBeyondBudgetAndReadsBack) {
  const test::TempDir spill;
  const std::string& dir = spill.path();
  const size_t one = Filled(16, 8, 0.0f).Bytes();
  StateCache cache(one + one / 2, dir);  // room for one state
  cache.Put(0, Filled(16, 8, 1.0f));
  cache.Put(1, Filled(16, 8, 2.0f));
  cache.EnforceBudget(1);
  EXPECT_LE(cache.ResidentBytes(), one + one / 2);
  EXPECT_EQ(cache.NumSpills(), 1);
  const PixelState& back = cache.Get(0);
  EXPECT_FLOAT_EQ(back.depth[3], 4.0f);
  EXPECT_EQ(back.mask[0], 5u);
  PixelState taken = cache.Take(1);
  EXPECT_FLOAT_EQ(taken.depth[0], 2.0f);
  EXPECT_FALSE(cache.Contains(1));
  EXPECT_TRUE(cache.Contains(0));
}

// The segmentation prior's edge map and the reliability classes travel with
// the state: present planes come back byte for byte, absent ones stay absent.
TEST(StateCache, SpillKeepsPriorEdgesAndClasses) {
  const test::TempDir spill;
  const std::string& dir = spill.path();
  PixelState with_edges = Filled(16, 8, 1.0f);
  with_edges.edges.assign(with_edges.depth.size(), 0);
  for (size_t i = 0; i < with_edges.edges.size(); i += 3)
    with_edges.edges[i] = static_cast<uint8_t>(i % 7);
  const std::vector<uint8_t> expected = with_edges.edges;
  with_edges.classes.assign(with_edges.depth.size(), 2);
  for (size_t i = 0; i < with_edges.classes.size(); i += 5) with_edges.classes[i] = 1;
  const std::vector<uint8_t> expected_classes = with_edges.classes;
  StateCache cache(1, dir);  // spills everything but the kept state
  cache.Put(0, std::move(with_edges));
  cache.Put(1, Filled(16, 8, 2.0f));
  cache.Put(2, Filled(16, 8, 3.0f));
  cache.EnforceBudget(2);
  EXPECT_EQ(cache.NumSpills(), 2);
  EXPECT_EQ(cache.Get(0).edges, expected);
  EXPECT_EQ(cache.Get(0).classes, expected_classes);
  EXPECT_FLOAT_EQ(cache.Get(0).depth[1], 2.0f);
  EXPECT_TRUE(cache.Get(1).edges.empty());
  EXPECT_TRUE(cache.Get(1).classes.empty());
  EXPECT_FLOAT_EQ(cache.Get(1).mask[0], 5u);
}

}  // namespace
}  // namespace msp

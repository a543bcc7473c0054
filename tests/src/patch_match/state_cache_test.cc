#include "patch_match/state_cache.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

// ReadDepth gives the depth, or the depth a geometric pass started from,
// of a resident state and of a spilled one alike, and leaves a spilled
// state in its file; the previous depth survives a spill.
TEST(StateCache, ReadsDepthsOfResidentAndSpilledStates) {
  const test::TempDir spill;
  PixelState first = Filled(16, 8, 1.0f);
  first.previous_depth.assign(first.depth.size(), 7.0f);
  first.previous_depth[5] = 9.0f;
  const std::vector<float> depth = first.depth, previous = first.previous_depth;
  StateCache cache(1, spill.path());
  cache.Put(0, std::move(first));
  EXPECT_EQ(cache.ReadDepth(0, false), depth);
  EXPECT_EQ(cache.ReadDepth(0, true), previous);
  cache.Put(1, Filled(16, 8, 2.0f));
  cache.EnforceBudget(1);
  ASSERT_EQ(cache.NumSpills(), 1);
  EXPECT_EQ(cache.ReadDepth(0, false), depth);
  EXPECT_EQ(cache.ReadDepth(0, true), previous);
  EXPECT_EQ(cache.ResidentBytes(), Filled(16, 8, 0.0f).Bytes());  // still spilled
  // A state without a previous depth has none to give.
  EXPECT_THROW(cache.ReadDepth(1, true), std::logic_error);
  const PixelState& back = cache.Get(0);
  EXPECT_EQ(back.previous_depth, previous);
  EXPECT_EQ(back.depth, depth);
  EXPECT_TRUE(cache.Get(1).previous_depth.empty());
}

}  // namespace
}  // namespace msp

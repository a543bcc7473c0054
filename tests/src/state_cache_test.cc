#include "state_cache.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace msp {
namespace {

PixelState Filled(int w, int h, float value) {
  PixelState s(w, h);
  for (size_t i = 0; i < s.depth.size(); ++i) s.depth[i] = value + static_cast<float>(i);
  s.mask[0] = 5u;
  return s;
}

TEST(StateCache, SpillsBeyondBudgetAndReadsBack) {
  char dir_template[] = "/tmp/msp_state_cache_XXXXXX";
  const std::string dir = mkdtemp(dir_template);
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

}  // namespace
}  // namespace msp

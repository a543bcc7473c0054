#include "core/math/rng.h"

#include <gtest/gtest.h>

namespace msp {
namespace core {
namespace {

TEST(Rng, SameKeySameNumbers) {
  Rng a = MakeRng(RngKey(1, 2, 3, 4, 5)), b = MakeRng(RngKey(1, 2, 3, 4, 5));
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.Uniform(), b.Uniform());
}

TEST(Rng, EveryKeyPartMatters) {
  const uint64_t base = RngKey(1, 2, 3, 4, 5);
  EXPECT_NE(base, RngKey(0, 2, 3, 4, 5));
  EXPECT_NE(base, RngKey(1, 0, 3, 4, 5));
  EXPECT_NE(base, RngKey(1, 2, 0, 4, 5));
  EXPECT_NE(base, RngKey(1, 2, 3, 0, 5));
  EXPECT_NE(base, RngKey(1, 2, 3, 4, 0));
}

TEST(Rng, UniformInUnitIntervalWithRightMean) {
  Rng rng = MakeRng(RngKey(7, 0, 0, 0, 0));
  double sum = 0.0;
  constexpr int kDraws = 100000;
  for (int i = 0; i < kDraws; ++i) {
    const float u = rng.Uniform();
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
  }
  EXPECT_NEAR(sum / kDraws, 0.5, 0.01);
}

}  // namespace
}  // namespace core
}  // namespace msp

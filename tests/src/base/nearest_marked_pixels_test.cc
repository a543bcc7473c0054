#include "base/nearest_marked_pixels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/deformable/deformable_limits.h"
#include "core/math/rng.h"

namespace msp {
namespace {

int SquaredDistance(int a, int b, int width) {
  const int dx = a % width - b % width, dy = a / width - b / width;
  return dx * dx + dy * dy;
}

// Classes with `share` of the pixels reliable, the rest unreliable or unknown.
std::vector<uint8_t> RandomLayout(int width, int height, float share, uint64_t seed) {
  std::vector<uint8_t> classes(width * height);
  for (int i = 0; i < width * height; ++i) {
    const float u = core::RandomUniform(core::Mix64(seed), i);
    classes[i] = u < share ? core::kReliable
                           : (u < 0.5f + 0.5f * share ? core::kUnreliable : core::kUnknown);
  }
  return classes;
}

void ExpectMatchesBruteForce(const std::vector<uint8_t>& classes, int width, int height,
                             int threads) {
  const std::vector<int> nearest = NearestReliablePixels(classes.data(), width, height, threads);
  ASSERT_EQ(nearest.size(), classes.size());
  for (int i = 0; i < width * height; ++i) {
    int best = -1;
    for (int q = 0; q < width * height; ++q) {
      if (classes[q] != core::kReliable) continue;
      if (best < 0 || SquaredDistance(i, q, width) < SquaredDistance(i, best, width)) best = q;
    }
    if (best < 0) {
      EXPECT_EQ(nearest[i], -1);
      continue;
    }
    ASSERT_GE(nearest[i], 0) << "pixel " << i;
    EXPECT_EQ(classes[nearest[i]], core::kReliable);
    // Ties may pick another pixel: the distance is what must be exact.
    EXPECT_EQ(SquaredDistance(i, nearest[i], width), SquaredDistance(i, best, width))
        << "pixel " << i;
  }
}

TEST(NearestReliable, MatchesBruteForceOnRandomLayouts) {
  ExpectMatchesBruteForce(RandomLayout(53, 41, 0.02f, 1), 53, 41, 1);
  ExpectMatchesBruteForce(RandomLayout(53, 41, 0.3f, 2), 53, 41, 2);
  ExpectMatchesBruteForce(RandomLayout(17, 64, 0.005f, 3), 17, 64, 3);
}

TEST(NearestReliable, ReliablePixelsAreTheirOwnNearest) {
  const std::vector<uint8_t> classes = RandomLayout(30, 20, 0.2f, 4);
  const std::vector<int> nearest = NearestReliablePixels(classes.data(), 30, 20, 1);
  for (int i = 0; i < 30 * 20; ++i) {
    if (classes[i] == core::kReliable) {
      EXPECT_EQ(nearest[i], i);
    }
  }
}

TEST(NearestReliable, SinglePixelAndEmptyImages) {
  std::vector<uint8_t> classes(40 * 30, core::kUnreliable);
  EXPECT_EQ(NearestReliablePixels(classes.data(), 40, 30, 2), std::vector<int>(40 * 30, -1));
  classes[7 * 40 + 33] = core::kReliable;
  EXPECT_EQ(NearestReliablePixels(classes.data(), 40, 30, 2),
            std::vector<int>(40 * 30, 7 * 40 + 33));
}

// Marks (the depth edges of the anchor search) take the same transform: the
// nearest marked pixel is at the nearest reliable pixel's distance when the
// marked pixels are the reliable ones.
TEST(NearestReliable, MarkedPixelsTakeTheSameTransform) {
  const std::vector<uint8_t> classes = RandomLayout(53, 41, 0.05f, 5);
  std::vector<uint8_t> marks(classes.size());
  for (size_t i = 0; i < classes.size(); ++i) marks[i] = classes[i] == core::kReliable ? 7 : 0;
  const std::vector<int> reliable = NearestReliablePixels(classes.data(), 53, 41, 1);
  const std::vector<int> marked = NearestMarkedPixels(marks.data(), 53, 41, 2);
  ASSERT_EQ(marked.size(), reliable.size());
  for (int i = 0; i < 53 * 41; ++i) {
    ASSERT_GE(marked[i], 0);
    EXPECT_NE(marks[marked[i]], 0);
    EXPECT_EQ(SquaredDistance(i, marked[i], 53), SquaredDistance(i, reliable[i], 53));
  }
}

}  // namespace
}  // namespace msp

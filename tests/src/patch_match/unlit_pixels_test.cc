#include "patch_match/unlit_pixels.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

namespace msp {
namespace {

constexpr float kBlackLevel = 0.03f;

// A 20x10 image at 0.01 (below the level) but for one pixel at `bright`.
DenseMap DarkImageWithOnePixel(int bright_row, int bright_col, float bright) {
  DenseMap gray(20, 10, 1);
  for (float& v : gray.data) v = 0.01f;
  gray.At(bright_row, bright_col) = bright;
  return gray;
}

TEST(UnlitPixels, AWindowIsUnlitExactlyWhenNoneOfItsPixelsReachesTheLevel) {
  const int radius = 2;
  const DenseMap gray = DarkImageWithOnePixel(5, 8, 0.5f);
  const std::vector<uint8_t> unlit = UnlitPixels(gray, radius, kBlackLevel);
  ASSERT_EQ(unlit.size(), gray.data.size());
  for (int row = 0; row < gray.height; ++row) {
    for (int col = 0; col < gray.width; ++col) {
      const bool sees_bright = std::abs(row - 5) <= radius && std::abs(col - 8) <= radius;
      EXPECT_EQ(unlit[row * gray.width + col], sees_bright ? 0 : 1) << row << " " << col;
    }
  }
}

TEST(UnlitPixels, APixelAtTheLevelIsLit) {
  const std::vector<uint8_t> unlit =
      UnlitPixels(DarkImageWithOnePixel(0, 0, kBlackLevel), 1, kBlackLevel);
  ASSERT_FALSE(unlit.empty());
  EXPECT_EQ(unlit[0], 0);
  EXPECT_EQ(unlit[1 * 20 + 1], 0);  // the corner pixel is in its window
  EXPECT_EQ(unlit[2 * 20 + 2], 1);
}

TEST(UnlitPixels, EmptyWhenOffOrWhenEveryWindowIsLit) {
  EXPECT_TRUE(UnlitPixels(DarkImageWithOnePixel(5, 8, 0.5f), 2, 0.0f).empty());
  DenseMap lit(20, 10, 1);
  for (float& v : lit.data) v = 0.2f;
  EXPECT_TRUE(UnlitPixels(lit, 2, kBlackLevel).empty());
}

}  // namespace
}  // namespace msp

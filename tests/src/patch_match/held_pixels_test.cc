#include "patch_match/held_pixels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tests/support/plane_scene.h"

namespace msp {
namespace {

// The textured plane with its left half painted flat: the flat half's
// windows are weakly textured, the textured half's are not, and the windows
// across the boundary see texture.
TEST(HeldPixels, MarksTheWindowsWithoutTexture) {
  test::PlaneScene scene;
  test::MakeScene(4.0f, true, &scene);
  const int width = scene.ref.width, height = scene.ref.height, half = width / 2;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < half; ++col) scene.ref_image.At(col, row) = 0.5f;
  }
  const std::vector<uint8_t> weak = WeaklyTexturedPixels(scene.params, 2);
  ASSERT_EQ(weak.size(), static_cast<size_t>(width) * height);
  const int radius = scene.params.ncc.window_radius, row = height / 2;
  for (int col = 0; col < width; ++col) {
    const int expected = col + radius < half ? 1 : 0;
    EXPECT_EQ(weak[static_cast<size_t>(row) * width + col], expected) << col;
  }
}

TEST(HeldPixels, NoneOnATexturedImage) {
  test::PlaneScene scene;
  test::MakeScene(4.0f, true, &scene);
  EXPECT_TRUE(WeaklyTexturedPixels(scene.params, 2).empty());
}

}  // namespace
}  // namespace msp

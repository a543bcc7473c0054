#include "patch_match/held_pixels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tests/support/plane_scene.h"

namespace msp {
namespace {

// The textured plane z = 4 with its left half painted flat; the state holds
// the true plane everywhere.
void HalfFlatScene(test::PlaneScene* scene) {
  test::MakeScene(4.0f, true, scene);
  const int half = scene->ref.width / 2;
  for (int row = 0; row < scene->ref.height; ++row) {
    for (int col = 0; col < half; ++col) scene->ref_image.At(col, row) = 0.5f;
  }
}

// The flat half's windows are weakly textured and held, the textured half's
// are not, nor the windows across the boundary, which see texture.
TEST(HeldPixels, HoldsTheWindowsWithoutTexture) {
  test::PlaneScene scene;
  HalfFlatScene(&scene);
  const std::vector<uint8_t> held = HeldPixels(scene.params, 2);
  const int width = scene.ref.width, half = width / 2;
  ASSERT_EQ(held.size(), static_cast<size_t>(width) * scene.ref.height);
  const int radius = scene.params.ncc.window_radius, row = scene.ref.height / 2;
  for (int col = 0; col < width; ++col) {
    EXPECT_EQ(held[static_cast<size_t>(row) * width + col], col + radius < half ? 1 : 0) << col;
  }
}

// A depth edge inside the flat half (two blank surfaces of one colour, the
// left 5 % nearer): the pixels whose neighbours a window's radius away lie
// on the other surface are swept, to put the edge in place; the rest held.
TEST(HeldPixels, SweepsThePixelsNearADepthEdge) {
  test::PlaneScene scene;
  HalfFlatScene(&scene);
  const int width = scene.ref.width, edge = width / 4;
  for (int row = 0; row < scene.ref.height; ++row) {
    for (int col = 0; col < edge; ++col) scene.state_depth[row * width + col] = 0.95f * 4.0f;
  }
  const std::vector<uint8_t> held = HeldPixels(scene.params, 2);
  const int radius = scene.params.ncc.window_radius, row = scene.ref.height / 2;
  for (int col = radius; col + radius < width / 2; ++col) {
    const bool near_edge = col < edge ? col + radius >= edge : col - radius < edge;
    EXPECT_EQ(held[static_cast<size_t>(row) * width + col], near_edge ? 0 : 1) << col;
  }
}

TEST(HeldPixels, NoneOnATexturedImage) {
  test::PlaneScene scene;
  test::MakeScene(4.0f, true, &scene);
  EXPECT_TRUE(HeldPixels(scene.params, 2).empty());
}

}  // namespace
}  // namespace msp

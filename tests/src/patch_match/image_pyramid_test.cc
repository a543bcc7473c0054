#include "patch_match/image_pyramid.h"

#include <gtest/gtest.h>

#include "core/math/plane.h"
#include "tests/support/cameras.h"

namespace msp {
namespace {

TEST(ImagePyramid, NumHalvings) {
  EXPECT_EQ(NumHalvings(640, 480, 1000), 0);
  EXPECT_EQ(NumHalvings(1536, 1024, 1000), 1);
  EXPECT_EQ(NumHalvings(4000, 3000, 1000), 2);
}

TEST(ImagePyramid, DownsampleAveragesBlocks) {
  DenseMap image(5, 4, 1);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 5; ++c) image.At(r, c) = static_cast<float>(r * 5 + c);
  }
  const DenseMap half = DownsampleHalf(image);
  ASSERT_EQ(half.width, 2);
  ASSERT_EQ(half.height, 2);
  EXPECT_FLOAT_EQ(half.At(0, 0), (0 + 1 + 5 + 6) / 4.0f);
  EXPECT_FLOAT_EQ(half.At(1, 1), (12 + 13 + 17 + 18) / 4.0f);
}

// A coarse pixel and the fine pixels it covers see the same 3D point of a
// fronto-parallel plane: the halved camera keeps the geometry.
TEST(ImagePyramid, HalvedCameraMatchesFinePixels) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  const core::Vec3 X = core::BackProject(coarse, 10.0f, 7.0f, 2.0f);
  float col, row;
  ASSERT_TRUE(core::ProjectCamPoint(fine, X, &col, &row));
  EXPECT_NEAR(col, 20.5f, 1e-4f);
  EXPECT_NEAR(row, 14.5f, 1e-4f);
}

TEST(ImagePyramid, UpsampleKeepsTiltedPlane) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  PixelState state(32, 24);
  const core::Vec3 n = core::Normalized(core::Vec3{0.3f, -0.2f, -1.0f});
  const core::Vec3 X0 = core::BackProject(coarse, 16.0f, 12.0f, 3.0f);
  const float dist = -core::Dot(n, X0);
  core::PixelStateView view = state.View();
  for (int r = 0; r < 24; ++r) {
    for (int c = 0; c < 32; ++c) {
      view.Set(view.Index(c, r),
               core::PlaneHypothesis{core::DepthOnPlane(coarse, n, dist, c, r), n});
    }
  }
  const PixelState up = UpsampleState(state, coarse, fine);
  for (int r = 0; r < 48; r += 5) {
    for (int c = 0; c < 64; c += 7) {
      EXPECT_NEAR(up.depth[r * 64 + c], core::DepthOnPlane(fine, n, dist, c, r), 1e-4f);
    }
  }
}

// Edge bits of the segmentation prior carry up by nearest neighbour: a coarse
// edge pixel becomes the 2x2 fine pixels it covers; no edges stay no edges.
TEST(ImagePyramid, UpsampleCarriesPriorEdgesByNearestNeighbour) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  PixelState state(32, 24);
  EXPECT_TRUE(UpsampleState(state, coarse, fine).edges.empty());
  state.edges.assign(32 * 24, 0);
  for (int r = 0; r < 24; ++r) state.edges[r * 32 + 10] = 3;  // a vertical edge at coarse col 10
  const PixelState up = UpsampleState(state, coarse, fine);
  ASSERT_EQ(up.edges.size(), 64u * 48u);
  for (int r = 0; r < 48; ++r) {
    for (int c = 0; c < 64; ++c) {
      EXPECT_EQ(up.edges[r * 64 + c], (c == 20 || c == 21) ? 3 : 0) << c << "," << r;
    }
  }
}

}  // namespace
}  // namespace msp

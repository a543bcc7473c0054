#include "patch_match/image_pyramid.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cstdint>

#include "core/math/plane.h"
#include "tests/support/cameras.h"

namespace msp {
namespace {

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

// The coarse state of one tilted plane, through the point at depth 3 of
// coarse pixel (16, 12) of `coarse` (32 x 24); each pixel's mask is its index.
PixelState TiltedPlaneState(const core::Camera& coarse, core::Vec3 n, float* dist) {
  *dist = -core::Dot(n, core::BackProject(coarse, 16.0f, 12.0f, 3.0f));
  PixelState state(32, 24);
  core::PixelStateView view = state.View();
  for (int r = 0; r < 24; ++r) {
    for (int c = 0; c < 32; ++c) {
      view.Set(view.Index(c, r),
               core::PlaneHypothesis{core::DepthOnPlane(coarse, n, *dist, c, r), n});
      state.mask[r * 32 + c] = static_cast<uint32_t>(r * 32 + c);
    }
  }
  return state;
}

// UpsampleStateJointBilateral of `state` from `coarse` to `fine`, guided by
// the fine reference image `guide` and its halved image.
PixelState UpsampleGuided(const PixelState& state, const DenseMap& guide,
                          const core::Camera& coarse, const core::Camera& fine) {
  return UpsampleStateJointBilateral(state, DownsampleHalf(guide), coarse, guide, fine);
}

TEST(ImagePyramid, UpsampleNearestKeepsTiltedPlane) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  const core::Vec3 n = core::Normalized(core::Vec3{0.3f, -0.2f, -1.0f});
  float dist;
  const PixelState state = TiltedPlaneState(coarse, n, &dist);
  const PixelState up = UpsampleStateNearest(state, coarse, fine);
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
  EXPECT_TRUE(UpsampleStateNearest(state, coarse, fine).edges.empty());
  state.edges.assign(32 * 24, 0);
  for (int r = 0; r < 24; ++r) state.edges[r * 32 + 10] = 3;  // a vertical edge at coarse col 10
  const PixelState up = UpsampleStateNearest(state, coarse, fine);
  ASSERT_EQ(up.edges.size(), 64u * 48u);
  for (int r = 0; r < 48; ++r) {
    for (int c = 0; c < 64; ++c) {
      EXPECT_EQ(up.edges[r * 64 + c], (c == 20 || c == 21) ? 3 : 0) << c << "," << r;
    }
  }
}

// Nearest neighbour is each fine pixel's coarse pixel (c / 2, r / 2): its
// plane on the fine ray, bit for bit, its mask and edge bits. This is what
// --MspStereo.advanced_joint_bilateral_upsampling false runs, as before the option.
TEST(ImagePyramid, UpsampleNearestIsTheCoarsePixelItFallsIn) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  PixelState state(32, 24);
  state.edges.assign(32 * 24, 0);
  core::PixelStateView view = state.View();
  for (int i = 0; i < 32 * 24; ++i) {
    const core::Vec3 n = core::Normalized(core::Vec3{0.01f * (i % 7), -0.02f * (i % 5), -1.0f});
    if (i % 11 != 0) view.Set(i, core::PlaneHypothesis{2.0f + 0.01f * (i % 13), n});
    state.mask[i] = static_cast<uint32_t>(i);
    state.edges[i] = static_cast<uint8_t>(i % 8);
  }
  const PixelState up = UpsampleStateNearest(state, coarse, fine);
  for (int r = 0; r < 48; ++r) {
    for (int c = 0; c < 64; ++c) {
      const int ci = (r / 2) * 32 + c / 2, fi = r * 64 + c;
      const core::PlaneHypothesis h = state.Plane(ci);
      const float depth =
          h.depth > 0.0f ? core::DepthOnPlane(fine, h.normal,
                                              core::PlaneDistance(coarse, c / 2, r / 2, h), c, r)
                         : 0.0f;
      ASSERT_EQ(up.depth[fi], depth) << c << "," << r;
      ASSERT_EQ(up.Plane(fi).normal.x, depth > 0.0f ? h.normal.x : 0.0f) << c << "," << r;
      ASSERT_EQ(up.mask[fi], state.mask[ci]) << c << "," << r;
      ASSERT_EQ(up.edges[fi], state.edges[ci]) << c << "," << r;
    }
  }
}

// A 64 x 48 reference whose grey steps from 0.2 to 0.8 between fine columns
// 20 and 21, inside coarse column 10, and its halved image.
constexpr int kEdgeCoarseCol = 10;
DenseMap StepGuide() {
  DenseMap guide(64, 48, 1);
  for (int r = 0; r < 48; ++r) {
    for (int c = 0; c < 64; ++c) guide.At(r, c) = c <= 2 * kEdgeCoarseCol ? 0.2f : 0.8f;
  }
  return guide;
}

// The planes z = 2 (left, mask 1) and z = 3 (right, mask 2) meet at the
// step; the coarse column the step crosses holds the left plane or the
// right one. Its edge bits mark it as the prior's edge.
PixelState StepState(bool edge_column_left) {
  const core::Vec3 n{0.0f, 0.0f, -1.0f};
  PixelState state(32, 24);
  state.edges.assign(32 * 24, 0);
  core::PixelStateView view = state.View();
  for (int r = 0; r < 24; ++r) {
    for (int c = 0; c < 32; ++c) {
      const bool left = c < kEdgeCoarseCol || (c == kEdgeCoarseCol && edge_column_left);
      view.Set(view.Index(c, r), core::PlaneHypothesis{left ? 2.0f : 3.0f, n});
      state.mask[r * 32 + c] = left ? 1u : 2u;
      if (c == kEdgeCoarseCol) state.edges[r * 32 + c] = 1;
    }
  }
  return state;
}

// The joint-bilateral vote puts both fine pixels of the crossed coarse
// column on the plane of their own side of the image edge; nearest neighbour
// gives both the plane the coarse pixel holds. Edge bits stay nearest's.
TEST(ImagePyramid, UpsampleJointBilateralSplitsACoarsePixelAtTheImageEdge) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  const DenseMap guide = StepGuide();
  for (bool edge_column_left : {true, false}) {
    const PixelState state = StepState(edge_column_left);
    const PixelState up = UpsampleGuided(state, guide, coarse, fine);
    const PixelState nearest = UpsampleStateNearest(state, coarse, fine);
    for (int r = 0; r < 48; ++r) {
      for (int c = 0; c < 64; ++c) {
        const int fi = r * 64 + c;
        const bool left = c <= 2 * kEdgeCoarseCol;
        EXPECT_FLOAT_EQ(up.depth[fi], left ? 2.0f : 3.0f) << c << "," << r;
        EXPECT_EQ(up.mask[fi], left ? 1u : 2u) << c << "," << r;
        EXPECT_EQ(up.Plane(fi).normal.z, -1.0f) << c << "," << r;
        EXPECT_EQ(up.edges[fi], nearest.edges[fi]) << c << "," << r;
      }
      // The fine pixel on the other side than the coarse pixel's plane.
      const int across = edge_column_left ? 2 * kEdgeCoarseCol + 1 : 2 * kEdgeCoarseCol;
      EXPECT_FLOAT_EQ(nearest.depth[r * 64 + across], edge_column_left ? 2.0f : 3.0f);
    }
  }
}

// One tilted plane under a textured guide: every fine pixel is on it, with
// its normal, from the coarse pixel nearest neighbour takes it from (the
// candidates agree, so they tie, and ties go to the coarse pixel the fine
// pixel falls in; the masks tell the coarse pixels apart).
TEST(ImagePyramid, UpsampleJointBilateralKeepsOnePlaneExactly) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  DenseMap guide(64, 48, 1);
  for (int r = 0; r < 48; ++r) {
    for (int c = 0; c < 64; ++c) guide.At(r, c) = 0.1f * ((7 * c + 13 * r) % 10);
  }
  const core::Vec3 n = core::Normalized(core::Vec3{0.3f, -0.2f, -1.0f});
  float dist;
  const PixelState state = TiltedPlaneState(coarse, n, &dist);
  const PixelState up = UpsampleGuided(state, guide, coarse, fine);
  const PixelState nearest = UpsampleStateNearest(state, coarse, fine);
  for (int r = 0; r < 48; ++r) {
    for (int c = 0; c < 64; ++c) {
      const int fi = r * 64 + c;
      const float depth = core::DepthOnPlane(fine, n, dist, c, r);
      EXPECT_NEAR(up.depth[fi], depth, 4.0f * FLT_EPSILON * depth) << c << "," << r;
      const core::Vec3 normal = up.Plane(fi).normal;
      EXPECT_EQ(normal.x, n.x);
      EXPECT_EQ(normal.y, n.y);
      EXPECT_EQ(normal.z, n.z);
      EXPECT_EQ(up.mask[fi], nearest.mask[fi]) << c << "," << r;  // the same coarse pixel
    }
  }
}

// The fine rows share out over threads with the planes one thread gives.
TEST(ImagePyramid, UpsampleJointBilateralOnThreadsIsTheSame) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  const DenseMap guide = StepGuide();
  const PixelState state = StepState(true);
  const PixelState one = UpsampleGuided(state, guide, coarse, fine);
  const PixelState three =
      UpsampleStateJointBilateral(state, DownsampleHalf(guide), coarse, guide, fine, 3);
  EXPECT_EQ(one.depth, three.depth);
  EXPECT_EQ(one.normal, three.normal);
  EXPECT_EQ(one.mask, three.mask);
}

// A coarse pixel without a plane takes one from its neighbours; a fine pixel
// whose 3x3 has none keeps nearest neighbour's empty plane and mask.
TEST(ImagePyramid, UpsampleJointBilateralFillsFromNeighbours) {
  const core::Camera fine = test::CentredCamera(64, 48);
  const core::Camera coarse = HalveCamera(fine, 32, 24);
  const DenseMap guide = StepGuide();
  PixelState state = StepState(true);
  const int hole = 5 * 32 + 3;
  state.depth[hole] = 0.0f;
  const PixelState up = UpsampleGuided(state, guide, coarse, fine);
  EXPECT_FLOAT_EQ(up.depth[10 * 64 + 6], 2.0f);
  EXPECT_EQ(up.mask[10 * 64 + 6], 1u);

  PixelState empty(32, 24);
  empty.mask.assign(32 * 24, 4u);
  const PixelState none = UpsampleGuided(empty, guide, coarse, fine);
  for (size_t i = 0; i < none.depth.size(); ++i) {
    ASSERT_EQ(none.depth[i], 0.0f);
    ASSERT_EQ(none.mask[i], 4u);
  }
}

}  // namespace
}  // namespace msp

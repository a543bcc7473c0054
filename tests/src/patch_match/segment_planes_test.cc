#include "patch_match/segment_planes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/patch_match/segment_plane.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace {

// A tilted world plane n . X + dist = 0 in the reference camera's frame.
const core::Vec3 kTiltedNormal = core::Normalized(core::Vec3{0.3f, -0.2f, -1.0f});

float TiltedDepth(const core::Camera& cam, int col, int row) {
  const core::Vec3 point{0.0f, 0.0f, 2.0f};  // the plane passes through (0, 0, 2)
  return core::HypothesisOnPlane(cam, col, row, kTiltedNormal, point).depth;
}

struct Fixture {
  test::PlaneScene scene;
  std::vector<int32_t> labels;
  std::vector<uint8_t> reliable;
};

// One segment over the whole image; the state holds the tilted plane's depth
// on the pixels `support` marks reliable, a wrong depth (+30 %) on every
// `outlier_every`-th of them (0: none).
Fixture MakeFixture(bool (*support)(int col, int row), int outlier_every) {
  Fixture f;
  test::MakeScene(2.0f, /*textured=*/true, &f.scene);
  const core::PassParams& p = f.scene.params;
  const int n = p.state.width * p.state.height;
  f.labels.assign(n, 1);
  f.reliable.assign(n, 0);
  int k = 0;
  for (int row = 0; row < p.state.height; ++row) {
    for (int col = 0; col < p.state.width; ++col) {
      if (!support(col, row)) continue;
      const int i = p.state.Index(col, row);
      f.reliable[i] = 1;
      const bool outlier = outlier_every > 0 && ++k % outlier_every == 0;
      p.state.depth[i] = TiltedDepth(p.ref_camera, col, row) * (outlier ? 1.3f : 1.0f);
    }
  }
  return f;
}

// An L: the image's left column band and bottom row band, as a wall's two
// creases would be.
bool LShape(int col, int row) { return col < 3 || row >= 145; }
// Two adjacent rows: planes through them fit, but they span one direction.
bool TwoRows(int, int row) { return row == 20 || row == 21; }

TEST(SegmentPlanes, FitsThePlaneOfAnLShapedSupportDespiteOutliers) {
  const Fixture f = MakeFixture(LShape, 4);  // 25 % outliers
  const std::vector<SegmentPlane> planes =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  ASSERT_EQ(planes.size(), 2u);
  const SegmentPlane& plane = planes[1];
  ASSERT_TRUE(plane.accepted);
  EXPECT_GT(plane.num_inliers, 0.7 * plane.num_support);
  EXPECT_LT(plane.num_inliers, 0.8 * plane.num_support);  // the outliers are out
  // Far from the support (the top right corner), the plane is the true one.
  const core::Camera& cam = f.scene.params.ref_camera;
  const int col = cam.width - 1, row = 0;
  const core::PlaneHypothesis h = core::HypothesisOnPlane(cam, col, row, plane.normal, plane.point);
  EXPECT_NEAR(h.depth, TiltedDepth(cam, col, row), 1e-3f * h.depth);
  EXPECT_GT(std::fabs(core::Dot(h.normal, kTiltedNormal)), std::cos(0.5f * 3.14159265f / 180));
}

// The depth map the first source sees of the plane `normal` . X + dist = 0
// through `point` (reference camera frame).
std::vector<float> SourceDepthOfPlane(const core::PassParams& p, core::Vec3 normal,
                                      core::Vec3 point) {
  const core::SourceView& src = p.src[0];
  const core::Vec3 n_src = core::Mul(src.rel.R, normal);
  const core::Vec3 point_src = core::Mul(src.rel.R, point) + src.rel.t;
  std::vector<float> depth(static_cast<size_t>(src.camera.width) * src.camera.height);
  for (int row = 0; row < src.camera.height; ++row) {
    for (int col = 0; col < src.camera.width; ++col) {
      depth[row * src.camera.width + col] =
          core::HypothesisOnPlane(src.camera, col, row, n_src, point_src).depth;
    }
  }
  return depth;
}

// The segment's plane (the tilted one, fitted from an L of support) is
// offered only when the source's depth map confirms it at least as often as
// the planes the pixels hold (z = 2 everywhere but the support).
TEST(SegmentPlanes, ConfirmationKeepsAPlaneTheViewsSeeAndDropsOneTheyContradict) {
  Fixture f = MakeFixture(LShape, 0);
  core::PassParams& p = f.scene.params;
  const std::vector<SegmentPlane> fitted = FitSegmentPlanes(p, f.labels, f.reliable, 7u);
  ASSERT_TRUE(fitted[1].accepted);
  const core::ImageView no_depth = p.src[0].depth;
  // Photometric pass: no source depth, nothing to confirm with.
  std::vector<SegmentPlane> planes = fitted;
  ConfirmSegmentPlanes(p, f.labels, 2, &planes);
  EXPECT_TRUE(planes[1].accepted);
  // The source sees the tilted plane: confirmed.
  const std::vector<float> tilted =
      SourceDepthOfPlane(p, kTiltedNormal, core::Vec3{0.0f, 0.0f, 2.0f});
  p.src[0].depth = core::ImageView{tilted.data(), p.src[0].camera.width, p.src[0].camera.height,
                                   p.src[0].camera.width};
  planes = fitted;
  ConfirmSegmentPlanes(p, f.labels, 2, &planes);
  EXPECT_TRUE(planes[1].accepted);
  // The source sees the pixels' own plane z = 2: the segment's plane is dropped.
  const std::vector<float> fronto =
      SourceDepthOfPlane(p, core::Vec3{0.0f, 0.0f, -1.0f}, core::Vec3{0.0f, 0.0f, 2.0f});
  p.src[0].depth = core::ImageView{fronto.data(), p.src[0].camera.width, p.src[0].camera.height,
                                   p.src[0].camera.width};
  planes = fitted;
  ConfirmSegmentPlanes(p, f.labels, 2, &planes);
  EXPECT_FALSE(planes[1].accepted);
  p.src[0].depth = no_depth;
}

// A window in a wall: segment 2 is the rectangle W, segment 1 the rest; all
// of the support lies on the wall's tilted plane. The wall's own support is
// the L of its creases; along W's outline the matched pixels (on both sides
// of the outline, as a matching window straddles it) are the wall's edge.
// With `interior`, W also has matched pixels of its own inside it.
constexpr int kWindowCols[2] = {60, 120};
constexpr int kWindowRows[2] = {20, 80};

bool InWindow(int col, int row) {
  return col >= kWindowCols[0] && col < kWindowCols[1] && row >= kWindowRows[0] &&
         row < kWindowRows[1];
}

// On W's outline: inside W next to the wall, or in the wall next to W.
bool OnWindowOutline(int col, int row) {
  const bool in = InWindow(col, row);
  const int nc[4] = {col - 1, col + 1, col, col};
  const int nr[4] = {row, row, row - 1, row + 1};
  for (int k = 0; k < 4; ++k) {
    if (InWindow(nc[k], nr[k]) != in) return true;
  }
  return false;
}

// Inside W, away from its outline: a cross through its middle.
bool InsideWindowCross(int col, int row) {
  return InWindow(col, row) && !OnWindowOutline(col, row) &&
         (col == (kWindowCols[0] + kWindowCols[1]) / 2 ||
          row == (kWindowRows[0] + kWindowRows[1]) / 2) &&
         col > kWindowCols[0] + 4 && col < kWindowCols[1] - 5 && row > kWindowRows[0] + 4 &&
         row < kWindowRows[1] - 5;
}

Fixture WallWithWindow(bool interior) {
  static bool with_interior = false;
  with_interior = interior;
  Fixture f = MakeFixture(
      [](int col, int row) {
        return LShape(col, row) || OnWindowOutline(col, row) ||
               (with_interior && InsideWindowCross(col, row));
      },
      0);
  const core::PixelStateView& s = f.scene.params.state;
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col)
      f.labels[s.Index(col, row)] = InWindow(col, row) ? 2 : 1;
  }
  return f;
}

TEST(SegmentPlanes, BorderOnlySupportGetsNoPlane) {
  const Fixture f = WallWithWindow(/*interior=*/false);
  const std::vector<SegmentPlane> planes =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_TRUE(planes[1].accepted);  // the wall: its creases are its own
  EXPECT_GT(planes[1].num_own, 0);
  EXPECT_LT(planes[1].num_own, planes[1].num_inliers);  // W's outline is not
  // W: a plane fits its outline (every inlier), but every inlier is where the
  // wall, holding the same plane, ends.
  EXPECT_GT(planes[2].num_inliers, 100);
  EXPECT_EQ(planes[2].num_own, 0);
  EXPECT_FALSE(planes[2].accepted);
  // Without the rule the outline, which spans two directions, gives W the
  // wall's plane.
  const std::vector<SegmentPlane> every_inlier =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u, /*own_support=*/false);
  EXPECT_TRUE(every_inlier[2].accepted);
}

TEST(SegmentPlanes, InteriorSupportGetsAPlane) {
  const Fixture f = WallWithWindow(/*interior=*/true);
  const std::vector<SegmentPlane> planes =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  EXPECT_TRUE(planes[1].accepted);
  EXPECT_TRUE(planes[2].accepted);
  EXPECT_GT(planes[2].num_own, 50);  // the cross inside W
  EXPECT_LT(planes[2].num_own, planes[2].num_inliers);
}

// A crease is two different planes meeting: the support on it counts for both.
TEST(SegmentPlanes, SupportOnACreaseIsOwnForBothPlanes) {
  Fixture f = MakeFixture(LShape, 0);
  const core::PassParams& p = f.scene.params;
  const core::PixelStateView& s = p.state;
  // Segment 2, the right half, holds a second plane through the crease: the
  // line the tilted plane shows along column `split`, the tilted normal
  // turned 30 degrees about it.
  const int split = s.width / 2;
  const core::Camera& cam = p.ref_camera;
  const core::Vec3 a = core::BackProject(cam, split, 0.0f, TiltedDepth(cam, split, 0));
  const core::Vec3 b =
      core::BackProject(cam, split, s.height - 1.0f, TiltedDepth(cam, split, s.height - 1));
  const core::Vec3 axis = core::Normalized(b - a);
  const float turn = 30.0f * 3.14159265f / 180.0f;
  const core::Vec3 other_normal = core::Normalized(
      std::cos(turn) * kTiltedNormal + std::sin(turn) * core::Cross(axis, kTiltedNormal));
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      f.labels[i] = col < split ? 1 : 2;
      // Support: the two columns of the crease and the bottom band.
      f.reliable[i] = col == split - 1 || col == split || row >= 145;
      if (!f.reliable[i]) continue;
      s.depth[i] = col < split ? TiltedDepth(cam, col, row)
                               : core::HypothesisOnPlane(cam, col, row, other_normal, a).depth;
    }
  }
  const std::vector<SegmentPlane> planes = FitSegmentPlanes(p, f.labels, f.reliable, 7u);
  ASSERT_EQ(planes.size(), 3u);
  EXPECT_TRUE(planes[1].accepted);
  EXPECT_TRUE(planes[2].accepted);
  EXPECT_EQ(planes[1].num_own, planes[1].num_inliers);
  EXPECT_EQ(planes[2].num_own, planes[2].num_inliers);
}

// The segments are fitted on several threads with the planes one thread
// gives: each segment's RANSAC draws from a generator of its own.
TEST(SegmentPlanes, ThreadsFitTheSamePlanes) {
  Fixture f = MakeFixture(LShape, 4);
  const core::PixelStateView& s = f.scene.params.state;
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      f.labels[s.Index(col, row)] = 1 + col / 16 + 20 * (row / 50);  // a grid of segments
      f.reliable[s.Index(col, row)] = f.reliable[s.Index(col, row)] || (col + row) % 3 == 0;
    }
  }
  const std::vector<SegmentPlane> one = FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  const std::vector<SegmentPlane> three =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u, true, 3);
  ASSERT_EQ(one.size(), three.size());
  int accepted = 0;
  for (size_t id = 1; id < one.size(); ++id) {
    accepted += one[id].accepted;
    EXPECT_EQ(one[id].accepted, three[id].accepted);
    EXPECT_EQ(one[id].num_inliers, three[id].num_inliers);
    EXPECT_EQ(one[id].num_own, three[id].num_own);
    EXPECT_EQ(one[id].normal.x, three[id].normal.x);
    EXPECT_EQ(one[id].point.z, three[id].point.z);
  }
  EXPECT_GT(accepted, 10);  // the comparison covers fitted planes
}

TEST(SegmentPlanes, RejectsSupportAlongOneLine) {
  // Every plane through the band nearly fits it: no plane for the segment.
  const Fixture f = MakeFixture(TwoRows, 0);
  const std::vector<SegmentPlane> planes =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  EXPECT_GT(planes[1].num_inliers, 0);
  EXPECT_FALSE(planes[1].accepted);
}

TEST(SegmentPlanes, RejectsSupportWithoutAMajorityPlane) {
  const Fixture f = MakeFixture(LShape, 0);
  // Two of three support pixels get a random depth: no plane holds half.
  const core::PixelStateView& s = f.scene.params.state;
  core::Rng rng = core::MakeRng(99u);
  int k = 0;
  for (int i = 0; i < s.width * s.height; ++i) {
    if (f.reliable[i] && ++k % 3 != 0) s.depth[i] = rng.Uniform(1.0f, 4.0f);
  }
  const std::vector<SegmentPlane> planes =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  EXPECT_GT(planes[1].num_inliers, 0.3 * planes[1].num_support);
  EXPECT_FALSE(planes[1].accepted);
}

TEST(SegmentPlanes, NoSupportNoPlane) {
  const Fixture f = MakeFixture([](int, int) { return false; }, 0);
  const std::vector<SegmentPlane> planes =
      FitSegmentPlanes(f.scene.params, f.labels, f.reliable, 7u);
  EXPECT_EQ(planes[1].num_support, 0);
  EXPECT_FALSE(planes[1].accepted);
}

TEST(SegmentPlanes, SegmentsWithinRegionsCutsSegmentsAtRegionEdges) {
  // Colour segments 1 (left), 2 (middle) and 3 (right), 0 = no segment;
  // regions 7 and 9, 0 = unlabelled.
  const std::vector<int32_t> segments = {1, 1, 2, 2, 0, 3,  //
                                         1, 1, 2, 2, 2, 3};
  const std::vector<int32_t> regions = {7, 7, 7, 9, 9, 0,  //
                                        9, 0, 7, 9, 9, 0};
  // Segment 1: its unlabelled pixel joins its larger piece (region 7);
  // segment 3, all unlabelled, stays whole.
  const std::vector<int32_t> expected = {1, 1, 2, 3, 0, 4,  //
                                         5, 1, 2, 3, 3, 4};
  EXPECT_EQ(SegmentsWithinRegions(segments, regions), expected);
  EXPECT_THROW(SegmentsWithinRegions(segments, {1, 2}), std::logic_error);
}

// The face of a pillar before a wall, both of one colour: one colour segment,
// whose densest support is the pillar's (its texture, at its depth), so the
// segment's one plane is the pillar's and the wall would be offered it. Cut
// at the regions of a segmentation that tells the two surfaces apart, the
// wall gets the plane of its own creases.
TEST(SegmentPlanes, RegionsGiveAWallBehindAPillarOfItsColourItsOwnPlane) {
  Fixture f = MakeFixture(LShape, 0);  // the wall: the tilted plane, support on its creases
  const core::PassParams& p = f.scene.params;
  const core::PixelStateView& s = p.state;
  const auto in_pillar = [](int col) { return col >= 20 && col < 60; };
  constexpr float kPillarDepth = 1.5f;  // fronto-parallel, before the wall (about 2)
  std::vector<int32_t> regions(f.labels.size());
  for (int row = 0; row < s.height; ++row) {
    for (int col = 0; col < s.width; ++col) {
      const int i = s.Index(col, row);
      regions[i] = in_pillar(col) ? 2 : 1;
      if (!in_pillar(col)) continue;
      f.reliable[i] = 1;
      s.depth[i] = kPillarDepth;
    }
  }
  const int col = 150, row = 75;  // a wall pixel
  const float wall_depth = TiltedDepth(p.ref_camera, col, row);
  const auto depth_on = [&](const SegmentPlane& plane) {
    return core::HypothesisOnPlane(p.ref_camera, col, row, plane.normal, plane.point).depth;
  };
  const std::vector<SegmentPlane> joint = FitSegmentPlanes(p, f.labels, f.reliable, 7u);
  ASSERT_EQ(joint.size(), 2u);
  ASSERT_TRUE(joint[1].accepted);
  EXPECT_NEAR(depth_on(joint[1]), kPillarDepth, 0.01f * kPillarDepth);

  const std::vector<int32_t> cut = SegmentsWithinRegions(f.labels, regions);
  const std::vector<SegmentPlane> planes = FitSegmentPlanes(p, cut, f.reliable, 7u);
  ASSERT_EQ(planes.size(), 3u);  // the wall first (its pixel (0, 0) comes first), the pillar
  ASSERT_TRUE(planes[1].accepted);
  EXPECT_NEAR(depth_on(planes[1]), wall_depth, 0.01f * wall_depth);
  ASSERT_TRUE(planes[2].accepted);
  EXPECT_NEAR(
      core::HypothesisOnPlane(p.ref_camera, 40, 75, planes[2].normal, planes[2].point).depth,
      kPillarDepth, 0.01f * kPillarDepth);
}

// OfferSegmentPlane on a textureless plane: any plane costs the same (kMaxCost),
// so with a margin the pixel takes the segment's plane; without, it keeps its own.
TEST(SegmentPlanes, TexturelessPixelTakesTheSegmentPlaneWithAMargin) {
  test::PlaneScene scene;
  test::MakeScene(2.0f, /*textured=*/false, &scene);
  const core::PassParams& p = scene.params;
  const int col = 100, row = 75, i = p.state.Index(col, row);
  const core::PlaneHypothesis wrong{2.6f, core::Vec3{0.0f, 0.0f, -1.0f}};
  const core::PlaneHypothesis offered{2.0f, core::Vec3{0.0f, 0.0f, -1.0f}};
  p.state.Set(i, wrong);
  core::OfferSegmentPlane(p, col, row, offered, 0.0f);
  EXPECT_FLOAT_EQ(p.state.depth[i], 2.6f);
  core::OfferSegmentPlane(p, col, row, offered, 0.1f);
  EXPECT_FLOAT_EQ(p.state.depth[i], 2.0f);
}

// On texture the views decide: the true plane is kept against a wrong
// offer, and a wrong plane gives way to the true one.
TEST(SegmentPlanes, TexturedPixelTakesOnlyABetterPlane) {
  test::PlaneScene scene;
  test::MakeScene(2.0f, /*textured=*/true, &scene);
  const core::PassParams& p = scene.params;
  const int col = 100, row = 75, i = p.state.Index(col, row);
  const core::PlaneHypothesis truth{2.0f, core::Vec3{0.0f, 0.0f, -1.0f}};
  const core::PlaneHypothesis wrong{2.3f, core::Normalized(core::Vec3{0.4f, 0.0f, -1.0f})};
  core::OfferSegmentPlane(p, col, row, wrong, 0.0f);
  EXPECT_FLOAT_EQ(p.state.depth[i], 2.0f);
  p.state.Set(i, wrong);
  core::OfferSegmentPlane(p, col, row, truth, 0.0f);
  EXPECT_FLOAT_EQ(p.state.depth[i], 2.0f);
  EXPECT_LT(p.state.cost[i], 0.2f);
}

}  // namespace
}  // namespace msp

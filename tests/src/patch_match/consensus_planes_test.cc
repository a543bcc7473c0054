#include "patch_match/consensus_planes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/patch_match/segment_plane.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace {

// A wall and a floor of one colour (one segment) meeting in a crease at row
// kCreaseRow: the wall faces the camera at depth 2, the floor is tilted.
const core::Vec3 kWallNormal{0.0f, 0.0f, -1.0f};
const core::Vec3 kWallPoint{0.0f, 0.0f, 2.0f};
const core::Vec3 kFloorNormal = core::Normalized(core::Vec3{0.0f, -1.0f, -0.5f});
constexpr int kCreaseRow = 75;  // half of the 150 rows

core::PlaneHypothesis OnSurface(const core::Camera& cam, int col, int row) {
  const core::PlaneHypothesis wall =
      core::HypothesisOnPlane(cam, col, row, kWallNormal, kWallPoint);
  if (row < kCreaseRow) return wall;
  // The floor through the wall's point on the crease row.
  const core::Vec3 crease =
      core::BackProject(cam, 0.0f, static_cast<float>(kCreaseRow),
                        core::HypothesisOnPlane(cam, 0, kCreaseRow, kWallNormal, kWallPoint).depth);
  return core::HypothesisOnPlane(cam, col, row, kFloorNormal, crease);
}

// Depth noise of +-1 % (uniform, seeded) on a pixel's true plane: the scatter
// of confirmed depths on a blank surface (the views agree within 1 %).
float Noise(int i) {
  return core::RandomUniform(0x5EEDu, static_cast<uint32_t>(i)) * 0.02f - 0.01f;
}

struct Fixture {
  test::PlaneScene scene;
  std::vector<int32_t> labels;
  std::vector<uint8_t> evidence;
};

// A blank image (every window weakly textured) with one source view; every
// pixel holds its surface's plane with Noise, every third is confirmed; the
// pixels of column band [70, 80) are 20 % too near (another surface's plane
// carried on) and unconfirmed.
Fixture MakeFixture() {
  Fixture f;
  test::MakeScene(2.0f, /*textured=*/false, &f.scene);
  test::AddSourceView(test::SourceCamera(), &f.scene);
  const core::PassParams& p = f.scene.params;
  const int n = p.state.width * p.state.height;
  f.labels.assign(n, 1);
  f.evidence.assign(n, 0);
  for (int row = 0; row < p.state.height; ++row) {
    for (int col = 0; col < p.state.width; ++col) {
      const int i = p.state.Index(col, row);
      core::PlaneHypothesis h = OnSurface(p.ref_camera, col, row);
      if (col >= 70 && col < 80) {
        h.depth *= 0.8f;
      } else {
        h.depth *= 1.0f + Noise(i);
        f.evidence[i] = i % 3 == 0;
      }
      p.state.Set(i, h);
    }
  }
  return f;
}

float RelativeError(const core::PassParams& p, int col, int row) {
  const float truth = OnSurface(p.ref_camera, col, row).depth;
  return std::fabs(p.state.depth[p.state.Index(col, row)] - truth) / truth;
}

// Two planes in one segment: the wall's and the floor's, each from its own
// confirmed points, and the noisy pixels of both take their own surface's.
TEST(ConsensusPlanes, NoisyPixelsOfTwoSurfacesInOneSegmentTakeTheirOwnPlane) {
  Fixture f = MakeFixture();
  const core::PassParams& p = f.scene.params;
  int off_before = 0, off_after = 0, total = 0;
  std::vector<float> before(f.scene.state_depth);
  for (int row = 0; row < p.state.height; ++row) {
    for (int col = 0; col < 70; ++col) off_before += RelativeError(p, col, row) > 0.005f ? 1 : 0;
  }
  const ConsensusPlanesReport r = OfferConsensusPlanes(p, f.labels, f.evidence, kSegmentOffer, 2);
  EXPECT_EQ(r.num_planes, 2);
  EXPECT_GT(r.num_taken, 0);
  for (int row = 0; row < p.state.height; ++row) {
    for (int col = 0; col < 70; ++col) {
      off_after += RelativeError(p, col, row) > 0.005f ? 1 : 0;
      ++total;
    }
  }
  EXPECT_GT(off_before, total / 2);
  EXPECT_LT(off_after, total / 50);
  // The band 20 % off lies on no plane within the tolerance: left as it was.
  for (int row = 0; row < p.state.height; row += 7) {
    const int i = p.state.Index(75, row);
    EXPECT_EQ(p.state.depth[i], before[i]);
  }
}

// A plane reaches no further than its segment: with the floor a segment of
// its own and no confirmed pixel there, the floor's noisy pixels keep their
// depths while the wall's are put on the wall's plane.
TEST(ConsensusPlanes, APlaneStaysInItsSegment) {
  Fixture f = MakeFixture();
  const core::PassParams& p = f.scene.params;
  for (int row = kCreaseRow; row < p.state.height; ++row) {
    for (int col = 0; col < p.state.width; ++col) {
      const int i = p.state.Index(col, row);
      f.labels[i] = 2;
      f.evidence[i] = 0;
    }
  }
  const std::vector<float> before(f.scene.state_depth);
  const ConsensusPlanesReport r = OfferConsensusPlanes(p, f.labels, f.evidence, kSegmentOffer, 1);
  EXPECT_EQ(r.num_planes, 1);
  for (int row = kCreaseRow; row < p.state.height; ++row) {
    for (int col = 0; col < p.state.width; ++col) {
      const int i = p.state.Index(col, row);
      ASSERT_EQ(p.state.depth[i], before[i]) << col << "," << row;
    }
  }
  EXPECT_LT(RelativeError(p, 30, kCreaseRow / 2), 0.005f);
}

// A region of the user's masks is one surface: with no depth bound, the band
// 20 % off (another surface's plane carried on) takes its own surface's
// plane too; with the colour segments' bound it keeps its depth.
TEST(ConsensusPlanes, InAMaskRegionEveryWeaklyTexturedPixelTakesItsPlane) {
  Fixture f = MakeFixture();
  const core::PassParams& p = f.scene.params;
  for (int row = kCreaseRow; row < p.state.height; ++row) {
    for (int col = 0; col < p.state.width; ++col) f.labels[p.state.Index(col, row)] = 2;
  }
  OfferConsensusPlanes(p, f.labels, f.evidence, kMaskRegionOffer, 2);
  int band = 0, on_plane = 0;
  for (int row = 0; row < p.state.height; ++row) {
    for (int col = 70; col < 80; ++col) {
      on_plane += RelativeError(p, col, row) < 0.005f ? 1 : 0;
      ++band;
    }
  }
  EXPECT_GT(on_plane, 0.95 * band);
}

// A mask region that joins two surfaces (two planes among its confirmed
// pixels) is not taken as one: its planes go only to the pixels within 3 %,
// as a colour segment's, and the band 20 % off keeps its depth.
TEST(ConsensusPlanes, AMaskRegionOfTwoPlanesIsOfferedAsAColourSegment) {
  Fixture f = MakeFixture();
  const core::PassParams& p = f.scene.params;
  const std::vector<float> before(f.scene.state_depth);
  const ConsensusPlanesReport r =
      OfferConsensusPlanes(p, f.labels, f.evidence, kMaskRegionOffer, 2);
  EXPECT_EQ(r.num_planes, 2);
  for (int row = 0; row < p.state.height; row += 7) {
    const int i = p.state.Index(75, row);
    EXPECT_EQ(p.state.depth[i], before[i]);
  }
  EXPECT_LT(RelativeError(p, 30, kCreaseRow / 2), 0.005f);
}

// Sequential RANSAC: two planes with their shares of the points and outliers
// scattered between them; the same key gives the same planes.
TEST(ConsensusPlanes, FitsEachPlaneOnceAndIsDeterministic) {
  std::vector<core::Vec3> points, rays;
  for (int k = 0; k < 900; ++k) {
    const float x = core::RandomUniform(1u, k) - 0.5f, y = core::RandomUniform(2u, k) - 0.5f;
    const core::Vec3 ray{x, y, 1.0f};
    float depth;
    if (k < 500) {
      depth = 3.0f;  // z = 3
    } else if (k < 800) {
      depth = 2.0f / (1.0f + 0.5f * y);  // tilted: z + 0.5 y z = 2
    } else {
      depth = 1.0f + 3.0f * core::RandomUniform(3u, k);  // outliers
    }
    rays.push_back(ray);
    points.push_back(depth * ray);
  }
  const std::vector<ConsensusPlane> planes = FitConsensusPlanes(points, rays, 50, 7u);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_GE(planes[0].num_inliers, 500);
  EXPECT_LT(planes[0].num_inliers, 560);
  EXPECT_NEAR(std::fabs(planes[0].normal.z), 1.0f, 1e-3f);
  EXPECT_GE(planes[1].num_inliers, 300);
  EXPECT_LT(std::fabs(planes[1].normal.z), 0.95f);
  const std::vector<ConsensusPlane> again = FitConsensusPlanes(points, rays, 50, 7u);
  ASSERT_EQ(again.size(), planes.size());
  EXPECT_EQ(again[1].point.x, planes[1].point.x);
}

}  // namespace
}  // namespace msp

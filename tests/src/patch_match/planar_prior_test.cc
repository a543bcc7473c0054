#include "patch_match/planar_prior.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math/plane.h"
#include "core/patch_match/segment_plane.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace {

// The floor: a tilted plane through (0, 0, 2.5); the box: a face over
// columns [20, 60) that meets the floor in a crease through the floor's point
// at (60, 75). Reference camera frame.
const core::Vec3 kFloorNormal = core::Normalized(core::Vec3{0.0f, -0.6f, -1.0f});
const core::Vec3 kFloorPoint{0.0f, 0.0f, 2.5f};
const core::Vec3 kBoxNormal = core::Normalized(core::Vec3{0.6f, 0.0f, -1.0f});
constexpr int kBoxBegin = 20, kBoxEnd = 60;
// A blank patch of floor right of the box: no pixel there is confirmed.
constexpr int kPatchCol0 = 64, kPatchCol1 = 90, kPatchRow0 = 60, kPatchRow1 = 90;

bool BoxColumn(int col) { return col >= kBoxBegin && col < kBoxEnd; }
bool InPatch(int col, int row) {
  return col >= kPatchCol0 && col < kPatchCol1 && row >= kPatchRow0 && row < kPatchRow1;
}

core::PlaneHypothesis OnFloor(const core::Camera& cam, int col, int row) {
  return core::HypothesisOnPlane(cam, col, row, kFloorNormal, kFloorPoint);
}
float FloorDepth(const core::Camera& cam, int col, int row) { return OnFloor(cam, col, row).depth; }
core::PlaneHypothesis OnBox(const core::Camera& cam, int col, int row) {
  const float d = FloorDepth(cam, 60, 75);
  return core::HypothesisOnPlane(cam, col, row, kBoxNormal, core::BackProject(cam, 60, 75, d));
}

struct Fixture {
  test::PlaneScene scene;
  std::vector<int32_t> labels;    // 1 floor, 2 box
  std::vector<uint8_t> evidence;  // confirmed pixels
};

// A blank image (every window weakly textured: the views cannot choose, so a
// pixel takes an offered plane) with one source view. Confirmed pixels hold
// their surface's plane; the patch holds the box's plane carried on past the
// crease, as the sweeps leave a blank floor next to a box.
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
      if (BoxColumn(col)) {
        f.labels[i] = 2;
        p.state.Set(i, OnBox(p.ref_camera, col, row));
        f.evidence[i] = 1;
      } else if (InPatch(col, row)) {
        p.state.Set(i, OnBox(p.ref_camera, col, row));
      } else {
        p.state.Set(i, OnFloor(p.ref_camera, col, row));
        f.evidence[i] = 1;
      }
    }
  }
  return f;
}

// A pixel on the floor next to the box takes the floor's plane, not the box's.
TEST(PlanarPrior, AFloorPixelNextToABoxTakesTheFloorsPlane) {
  Fixture f = MakeFixture();
  const core::PassParams& p = f.scene.params;
  const PlanarPriorReport r = OfferPriorPlanes(p, f.labels, f.evidence, 2);
  EXPECT_GT(r.num_triangles, 0);
  EXPECT_GT(r.num_taken, 0);
  int on_floor = 0, patch = 0;
  for (int row = kPatchRow0; row < kPatchRow1; ++row) {
    for (int col = kPatchCol0; col < kPatchCol1; ++col) {
      const float d = p.state.depth[p.state.Index(col, row)];
      on_floor += std::fabs(d - FloorDepth(p.ref_camera, col, row)) <
                          1e-3f * FloorDepth(p.ref_camera, col, row)
                      ? 1
                      : 0;
      ++patch;
    }
  }
  EXPECT_GT(on_floor, 0.9 * patch);
  // The box's pixels were confirmed: they keep their plane.
  EXPECT_FLOAT_EQ(p.state.depth[p.state.Index(40, 75)], OnBox(p.ref_camera, 40, 75).depth);
}

// No triangle reaches across a region edge: with the labels every triangle's
// corners lie on one surface; without them some join the box and the floor
// across the crease, and their plane is neither's.
TEST(PlanarPrior, NoTriangleAcrossARegionEdge) {
  const Fixture f = MakeFixture();
  const core::PassParams& p = f.scene.params;
  std::vector<int> vertices;
  for (int row = 2; row < p.state.height; row += 6) {
    for (int col = 2; col < p.state.width; col += 6) {
      if (!f.evidence[p.state.Index(col, row)]) continue;
      vertices.push_back(col);
      vertices.push_back(row);
    }
  }
  const auto mixed = [&](const std::vector<PriorTriangle>& triangles) {
    int count = 0;
    for (const PriorTriangle& t : triangles) {
      const bool box0 = BoxColumn(t.corner[0][0]);
      count += BoxColumn(t.corner[1][0]) != box0 || BoxColumn(t.corner[2][0]) != box0 ? 1 : 0;
    }
    return count;
  };
  const std::vector<PriorTriangle> bounded = PriorTriangles(p, f.labels, vertices);
  const std::vector<PriorTriangle> unbounded = PriorTriangles(p, {}, vertices);
  EXPECT_GT(bounded.size(), 100u);
  EXPECT_EQ(mixed(bounded), 0);
  EXPECT_GT(mixed(unbounded), 0);
}

// Outside geometric passes there are no other views' depths: nothing changes.
TEST(PlanarPrior, PhotometricPassesAreLeftAlone) {
  Fixture f = MakeFixture();
  core::PassParams& p = f.scene.params;
  p.geometric = 0;
  const std::vector<float> before = f.scene.state_depth;
  core::FilterParams filter{0.1f, 0.05f, 1, 1.0f, 1};
  const PlanarPriorReport r = ApplyPlanarPrior(p, filter, f.labels, 1);
  EXPECT_EQ(r.num_offered, 0);
  EXPECT_EQ(f.scene.state_depth, before);
}

}  // namespace
}  // namespace msp

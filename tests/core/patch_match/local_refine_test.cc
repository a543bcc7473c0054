#include "core/patch_match/local_refine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "tests/support/plane_scene.h"

namespace msp {
namespace {

// The disparity (f b / depth) of the reference's pixel sweep at `depth`.
float Disparity(const core::PassParams& p, float depth) {
  return p.ref_camera.fx * core::MeanBaseline(p, 1u) / depth;
}

// The textured plane z = 4 and its centre pixel (col, row), state index i,
// with f b, the disparity times the depth, of the reference's sweep.
class LocalRefine : public ::testing::Test {
 protected:
  void SetUp() override {
    test::MakeScene(4.0f, true, &scene);
    col = scene.params.ref_camera.width / 2;
    row = scene.params.ref_camera.height / 2;
    i = scene.params.state.Index(col, row);
    fb = Disparity(scene.params, scene.depth) * scene.depth;
  }
  test::PlaneScene scene;
  int col = 0, row = 0, i = 0;
  float fb = 0.0f;
};

// A pixel 3 disparity pixels off the textured plane: the default sweep
// (+-5 px) lands on the plane; a sweep of +-1 px stays within 1 px of where
// it started, and lands on the plane from 1 px off.
TEST_F(LocalRefine, SweepsRefineRadiusPixelsOfDisparity) {
  core::PassParams& p = scene.params;
  const float truth = Disparity(p, scene.depth);

  EXPECT_EQ(p.refine_radius, core::kLocalRefineRadius);
  scene.state_depth[i] = core::DepthAtDisparityOffset(fb, scene.depth, 3.0f);
  core::LocalRefinePixel(p, col, row);
  EXPECT_NEAR(Disparity(p, scene.state_depth[i]), truth, 0.01f);

  p.refine_radius = 1;
  scene.state_depth[i] = core::DepthAtDisparityOffset(fb, scene.depth, 3.0f);
  core::LocalRefinePixel(p, col, row);
  EXPECT_GE(Disparity(p, scene.state_depth[i]), truth + 2.0f - 0.01f);

  scene.state_depth[i] = core::DepthAtDisparityOffset(fb, scene.depth, 1.0f);
  core::LocalRefinePixel(p, col, row);
  EXPECT_NEAR(Disparity(p, scene.state_depth[i]), truth, 0.01f);
}

// A held pixel (core::PassParams::held) is left where it is by the sweep.
TEST_F(LocalRefine, LeavesAHeldPixel) {
  core::PassParams& p = scene.params;
  const std::vector<uint8_t> held = test::OnePixelMask(p, col, row);
  p.held = held.data();
  const float off = core::DepthAtDisparityOffset(fb, scene.depth, 3.0f);
  scene.state_depth[i] = off;
  core::LocalRefinePixel(p, col, row);
  EXPECT_EQ(scene.state_depth[i], off);
  p.held = nullptr;
  core::LocalRefinePixel(p, col, row);
  EXPECT_NEAR(scene.state_depth[i], scene.depth, 0.01f * scene.depth);
}

}  // namespace
}  // namespace msp

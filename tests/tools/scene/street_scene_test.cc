#include "tools/scene/street_scene.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

#include "tools/scene/camera_rig.h"
#include "tools/scene/renderer.h"

namespace msp {
namespace scene {
namespace {

// Whether the ray through pixel (col, row) of `view` hits nothing.
bool IsSky(const Scene& scene, const PinholeView& view, int col, int row) {
  Hit hit;
  return !scene.Intersect(view.Center(), view.RayDirection(col, row), &hit);
}

// In every view of the street's rig the sky is open: it reaches the top
// border and a side border, and covers a fair share of the image, so the
// open-sky rule meets it as a user's street photograph shows it.
TEST(StreetScene, SkyReachesTheTopAndASideBorderInEveryView) {
  const Scene scene = MakeStreetScene(SkyKind::kBlue);
  RigOptions rig;
  rig.width = 80;
  rig.height = 60;
  for (const PinholeView& view : MakeCameraRig(StreetRig(rig), 1)) {
    int top = 0, side = 0, all = 0;
    for (int col = 0; col < view.width; ++col) top += IsSky(scene, view, col, 0);
    for (int row = 0; row < view.height; ++row) {
      side += IsSky(scene, view, 0, row) + IsSky(scene, view, view.width - 1, row);
      for (int col = 0; col < view.width; ++col) all += IsSky(scene, view, col, row);
    }
    EXPECT_GT(top, view.width / 4) << view.name;
    EXPECT_GT(side, 0) << view.name;
    EXPECT_GT(all, view.width * view.height / 10) << view.name;
    EXPECT_LT(all, view.width * view.height * 6 / 10) << view.name;
  }
}

// The sky's pixels have an empty ground truth, as the window's do.
TEST(StreetScene, SkyHasNoGroundTruthDepth) {
  const Scene scene = MakeStreetScene(SkyKind::kOvercast);
  RigOptions rig;
  rig.width = 64;
  rig.height = 48;
  const PinholeView view = MakeCameraRig(StreetRig(rig), 2)[3];
  const RenderedView rendered = RenderView(scene, view, 3, 2);
  int checked = 0;
  for (int row = 0; row < view.height; ++row) {
    for (int col = 0; col < view.width; ++col) {
      if (!IsSky(scene, view, col, row)) continue;
      EXPECT_EQ(rendered.depth.At(row, col), 0.0f);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

// The kinds of sky: the bundled scene's is as it was (its images stay byte
// for byte the same); the blue is deeper, the overcast grey, the clouds
// white patches on the blue, soft and not everywhere.
TEST(SkyKinds, EachSkyLooksAsNamed) {
  Scene scene;
  const Eigen::Vector3d horizon(1.0, 0.0, 0.0), up(0.0, 0.0, 1.0);
  EXPECT_TRUE(scene.SkyRadiance(horizon).isApprox(Eigen::Vector3d(0.86, 0.9, 0.95)));
  EXPECT_TRUE(scene.SkyRadiance(up).isApprox(Eigen::Vector3d(0.55, 0.7, 0.95)));
  scene.sky = SkyKind::kBlue;
  const Eigen::Vector3d blue = scene.SkyRadiance(up);
  EXPECT_LT(blue.mean(), 0.6);
  EXPECT_GT(blue.z() - blue.x(), 0.4);
  scene.sky = SkyKind::kOvercast;
  for (const Eigen::Vector3d& dir : {horizon, up}) {
    const Eigen::Vector3d grey = scene.SkyRadiance(dir);
    EXPECT_LT(grey.z() - grey.x(), 0.05);
    EXPECT_GT(grey.mean(), 0.7);
  }
  scene.sky = SkyKind::kClouds;
  int cloudy = 0, clear = 0, samples = 0;
  for (int a = 0; a < 40; ++a) {
    for (int b = 0; b < 40; ++b) {
      const Eigen::Vector3d dir =
          Eigen::Vector3d(-1.0 + 0.05 * a, -1.0 + 0.05 * b, 0.4).normalized();
      scene.sky = SkyKind::kBlue;
      const Eigen::Vector3d base = scene.SkyRadiance(dir);
      scene.sky = SkyKind::kClouds;
      const double whiter = scene.SkyRadiance(dir).x() - base.x();
      cloudy += whiter > 0.1;
      clear += whiter < 1e-9;
      ++samples;
    }
  }
  EXPECT_GT(cloudy, samples / 10);
  EXPECT_GT(clear, samples / 10);
}

}  // namespace
}  // namespace scene
}  // namespace msp

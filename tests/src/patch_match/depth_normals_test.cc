#include "patch_match/depth_normals.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/patch_match/segment_plane.h"
#include "tests/support/cameras.h"

namespace msp {
namespace {

const core::Vec3 kTilted = core::Normalized(core::Vec3{0.3f, -0.4f, -1.0f});
const core::Vec3 kFrontal{0.0f, 0.0f, -1.0f};

float AngleDegrees(core::Vec3 a, core::Vec3 b) {
  return std::acos(std::fmin(1.0f, std::fabs(core::Dot(a, b)))) * 180.0f / 3.14159265f;
}

core::Vec3 NormalAt(const DenseMap& normal, int row, int col) {
  return core::Vec3{normal.At(row, col, 0), normal.At(row, col, 1), normal.At(row, col, 2)};
}

// The depth of a plane through (0, 0, distance) with `n`, times 1 + a uniform
// noise of +-`noise` per pixel, as a sweep leaves a weakly textured wall.
void FillPlane(const core::Camera& cam, core::Vec3 n, float distance, float noise, int col0,
               int col1, DenseMap* depth) {
  core::Rng rng{core::RngKey(3u, 0u, 0u, 0u, 0u), 0u};
  for (int row = 0; row < depth->height; ++row) {
    for (int col = col0; col < col1; ++col) {
      const float d = core::HypothesisOnPlane(cam, col, row, n, core::Vec3{0, 0, distance}).depth;
      depth->At(row, col) = d * (1.0f + noise * (2.0f * rng.Uniform() - 1.0f));
    }
  }
}

// Scattered normals (what the sweeps leave on weak texture): 25 degrees off.
DenseMap ScatteredNormals(int width, int height) {
  DenseMap normal(width, height, 3);
  const core::Vec3 off = core::Normalized(core::Vec3{0.45f, 0.0f, -1.0f});
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      normal.At(row, col, 0) = off.x;
      normal.At(row, col, 1) = off.y;
      normal.At(row, col, 2) = off.z;
    }
  }
  return normal;
}

// A tilted wall whose depths scatter by 0.5 %: away from the image border
// (where the neighbourhood is one-sided) the fitted planes' normals are within
// 3 degrees of the wall's, where the given ones were 25 off.
TEST(DepthNormals, RecoversTheNormalOfANoisyPlane) {
  const core::Camera cam = test::ReferenceCamera();
  DenseMap depth(cam.width, cam.height, 1);
  FillPlane(cam, kTilted, 3.0f, 0.005f, 0, cam.width, &depth);
  DenseMap normal = ScatteredNormals(cam.width, cam.height);
  ASSERT_GT(AngleDegrees(NormalAt(normal, 75, 100), kTilted), 20.0f);
  NormalsFromDepth(cam, depth, 8, 2, &normal);
  for (int row = 8; row < cam.height - 8; row += 7) {
    for (int col = 8; col < cam.width - 8; col += 7) {
      const core::Vec3 n = NormalAt(normal, row, col);
      EXPECT_LT(AngleDegrees(n, kTilted), 3.0f) << col << "," << row;
      EXPECT_LT(core::Dot(n, core::ViewRay(cam, col, row)), 0.0f);  // faces the camera
    }
  }
}

// A depth edge: a frontal surface at 2 in front of the tilted one at 3. The
// pixels next to the edge fit their own surface only.
TEST(DepthNormals, KeepsToItsOwnSideOfADepthEdge) {
  const core::Camera cam = test::ReferenceCamera();
  DenseMap depth(cam.width, cam.height, 1);
  FillPlane(cam, kFrontal, 2.0f, 0.0f, 0, 100, &depth);
  FillPlane(cam, kTilted, 3.0f, 0.0f, 100, cam.width, &depth);
  DenseMap normal = ScatteredNormals(cam.width, cam.height);
  NormalsFromDepth(cam, depth, 8, 1, &normal);
  for (int row = 10; row < cam.height - 10; row += 10) {
    EXPECT_LT(AngleDegrees(NormalAt(normal, row, 99), kFrontal), 1.0f) << row;
    EXPECT_LT(AngleDegrees(NormalAt(normal, row, 100), kTilted), 1.0f) << row;
  }
}

// A pixel without a depth, or with too few neighbours on its surface, keeps
// the normal it had.
TEST(DepthNormals, LeavesPixelsWithoutSurroundingSurface) {
  const core::Camera cam = test::ReferenceCamera();
  DenseMap depth(cam.width, cam.height, 1);
  depth.At(75, 100) = 2.0f;  // alone
  DenseMap normal = ScatteredNormals(cam.width, cam.height);
  const DenseMap before = normal;
  NormalsFromDepth(cam, depth, 8, 2, &normal);
  EXPECT_EQ(normal.data, before.data);
}

}  // namespace
}  // namespace msp

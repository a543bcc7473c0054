#include "core/math/homography.h"

#include <gtest/gtest.h>

#include "core/math/plane.h"
#include "tests/support/cameras.h"

namespace msp {
namespace core {
namespace {

using test::ReferenceCamera;
using test::SourceCamera;

// The reference mapped onto itself by any plane is the identity.
TEST(Homography, SameCameraIsIdentity) {
  const Camera ref = ReferenceCamera();
  const RelativePose rel = ComputeRelativePose(ref, ref);
  const Mat3 H = ComputeHomography(ref, rel, Normalized(Vec3{0.2f, 0.1f, -1.0f}), 3.0f);
  const float scale = H.m[8];
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(H.m[i] / scale, (i % 4 == 0) ? 1.0f : 0.0f, 1e-6f);
}

// A pixel of a plane maps exactly where its 3D point projects in the source.
TEST(Homography, MapsPlanePointsToTheirProjections) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const RelativePose rel = ComputeRelativePose(ref, src);
  const PlaneHypothesis h{2.5f, Normalized(Vec3{0.3f, -0.2f, -1.0f})};
  const float dist = PlaneDistance(ref, 90, 70, h);
  const Mat3 H = ComputeHomography(ref, rel, h.normal, dist);
  for (int row = 10; row < 150; row += 37) {
    for (int col = 5; col < 200; col += 41) {
      const float depth = DepthOnPlane(ref, h.normal, dist, col, row);
      const Vec3 X = CamToWorld(ref, BackProject(ref, col, row, depth));
      float u_expected, v_expected, u, v;
      ASSERT_TRUE(ProjectCamPoint(src, WorldToCam(src, X), &u_expected, &v_expected));
      ASSERT_TRUE(ApplyHomography(H, col, row, &u, &v));
      EXPECT_NEAR(u, u_expected, 1e-3f);
      EXPECT_NEAR(v, v_expected, 1e-3f);
    }
  }
}

TEST(Homography, RelativePoseMapsReferenceToSourceFrame) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const RelativePose rel = ComputeRelativePose(ref, src);
  const Vec3 X_world{0.3f, -0.4f, 2.0f};
  const Vec3 expected = WorldToCam(src, X_world);
  const Vec3 got = Mul(rel.R, WorldToCam(ref, X_world)) + rel.t;
  EXPECT_NEAR(got.x, expected.x, 1e-5f);
  EXPECT_NEAR(got.y, expected.y, 1e-5f);
  EXPECT_NEAR(got.z, expected.z, 1e-5f);
}

}  // namespace
}  // namespace core
}  // namespace msp

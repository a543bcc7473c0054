#include "core/math/plane.h"

#include <gtest/gtest.h>

#include "tests/support/cameras.h"

namespace msp {
namespace core {
namespace {

TEST(Plane, PropagatedDepthStaysOnThePlane) {
  const Camera cam = test::ReferenceCamera();
  const PlaneHypothesis h{2.0f, Normalized(Vec3{0.2f, 0.3f, -1.0f})};
  const float d = PropagatedDepth(cam, 50, 60, h, 80, 20);
  const Vec3 p = BackProject(cam, 50, 60, 2.0f);
  const Vec3 q = BackProject(cam, 80, 20, d);
  EXPECT_NEAR(Dot(h.normal, q - p), 0.0f, 1e-5f);
}

TEST(Plane, FrontoParallelPlaneKeepsDepth) {
  const Camera cam = test::ReferenceCamera();
  const PlaneHypothesis h{2.0f, Vec3{0.0f, 0.0f, -1.0f}};
  EXPECT_NEAR(PropagatedDepth(cam, 10, 10, h, 190, 140), 2.0f, 1e-6f);
}

TEST(Plane, RandomAndPerturbedNormalsAreUnitAndFaceTheCamera) {
  const Camera cam = test::ReferenceCamera();
  Rng rng = MakeRng(3);
  for (int i = 0; i < 1000; ++i) {
    const int col = i % 200, row = (i * 7) % 150;
    const Vec3 n = RandomNormal(cam, col, row, &rng);
    EXPECT_NEAR(Norm(n), 1.0f, 1e-5f);
    EXPECT_LT(Dot(n, ViewRay(cam, col, row)), 0.0f);
    const Vec3 p = PerturbNormal(cam, col, row, n, 0.03f, &rng);
    EXPECT_NEAR(Norm(p), 1.0f, 1e-5f);
    EXPECT_LT(Dot(p, ViewRay(cam, col, row)), 0.0f);
    EXPECT_GT(Dot(p, n), 0.99f);  // a small rotation
  }
}

TEST(Plane, RandomHypothesisDepthInRange) {
  const Camera cam = test::ReferenceCamera();
  Rng rng = MakeRng(5);
  for (int i = 0; i < 200; ++i) {
    const PlaneHypothesis h = RandomHypothesis(cam, 3, 4, 1.5f, 2.5f, &rng);
    EXPECT_GE(h.depth, 1.5f);
    EXPECT_LE(h.depth, 2.5f);
  }
}

}  // namespace
}  // namespace core
}  // namespace msp

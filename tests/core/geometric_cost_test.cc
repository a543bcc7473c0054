#include "core/geometric_cost.h"

#include <gtest/gtest.h>

#include <vector>

#include "test_cameras.h"

namespace msp {
namespace core {
namespace {

using testing_cameras::Reference;
using testing_cameras::Source;

// Source depth map of the world plane z = 3 (reference frame = world frame).
std::vector<float> SourcePlaneDepth(const Camera& src) {
  std::vector<float> depth(src.width * src.height, 0.0f);
  for (int r = 0; r < src.height; ++r) {
    for (int c = 0; c < src.width; ++c) {
      // Ray from the source centre through (c, r), intersected with z = 3.
      const Vec3 dir = MulTransposed(src.R, ViewRay(src, c, r));
      const float s = (3.0f - src.center.z) / dir.z;
      depth[r * src.width + c] = WorldToCam(src, src.center + s * dir).z;
    }
  }
  return depth;
}

TEST(GeometricCost, ConsistentDepthReprojectsOntoItself) {
  const Camera ref = Reference(), src = Source();
  const std::vector<float> depth = SourcePlaneDepth(src);
  const ImageView view{depth.data(), src.width, src.height, src.width};
  // Reference depth of the plane z = 3 is 3 everywhere (R = I, C = 0). The
  // source depth is sampled at the nearest pixel: sub-pixel error remains.
  EXPECT_LT(ReprojectionError(ref, src, view, 100, 75, 3.0f, 3.0f), 0.05f);
  EXPECT_LT(ReprojectionError(ref, src, view, 60, 40, 3.0f, 3.0f), 0.05f);
}

TEST(GeometricCost, InconsistentDepthIsPenalisedAndClamped) {
  const Camera ref = Reference(), src = Source();
  const std::vector<float> depth = SourcePlaneDepth(src);
  const ImageView view{depth.data(), src.width, src.height, src.width};
  const float e = ReprojectionError(ref, src, view, 100, 75, 3.3f, 100.0f);
  EXPECT_GT(e, 1.0f);
  EXPECT_EQ(ReprojectionError(ref, src, view, 100, 75, 6.0f, 3.0f), 3.0f);
  const std::vector<float> empty(src.width * src.height, 0.0f);
  const ImageView none{empty.data(), src.width, src.height, src.width};
  EXPECT_EQ(ReprojectionError(ref, src, none, 100, 75, 3.0f, 3.0f), 3.0f);
}

}  // namespace
}  // namespace core
}  // namespace msp

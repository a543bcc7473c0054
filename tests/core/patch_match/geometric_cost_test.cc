#include "core/patch_match/geometric_cost.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/math/homography.h"
#include "tests/support/cameras.h"

namespace msp {
namespace core {
namespace {

using test::ReferenceCamera;
using test::SourceCamera;

// The source depth maps are of the world plane z = 3 (reference frame = world frame).
constexpr float kPlaneZ = 3.0f;

TEST(GeometricCost, ConsistentDepthReprojectsOntoItself) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const std::vector<float> depth = test::PlaneDepthMap(src, kPlaneZ);
  const ImageView view{depth.data(), src.width, src.height, src.width};
  // Reference depth of the plane z = 3 is 3 everywhere (R = I, C = 0). The
  // source depth is sampled at the nearest pixel: sub-pixel error remains.
  EXPECT_LT(ReprojectionError(ref, src, view, 100, 75, 3.0f, 3.0f), 0.05f);
  EXPECT_LT(ReprojectionError(ref, src, view, 60, 40, 3.0f, 3.0f), 0.05f);
}

TEST(GeometricCost, InconsistentDepthIsPenalisedAndClamped) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const std::vector<float> depth = test::PlaneDepthMap(src, kPlaneZ);
  const ImageView view{depth.data(), src.width, src.height, src.width};
  const float e = ReprojectionError(ref, src, view, 100, 75, 3.3f, 100.0f);
  EXPECT_GT(e, 1.0f);
  EXPECT_EQ(ReprojectionError(ref, src, view, 100, 75, 6.0f, 3.0f), 3.0f);
  const std::vector<float> empty(src.width * src.height, 0.0f);
  const ImageView none{empty.data(), src.width, src.height, src.width};
  EXPECT_EQ(ReprojectionError(ref, src, none, 100, 75, 3.0f, 3.0f), 3.0f);
}

// The composed maps give ReprojectionError's answer: consistent, penalised,
// clamped, off the source, and on a depth map of half the resolution.
TEST(GeometricCost, ComposedMapsGiveTheSameError) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const RelativePose rel = ComputeRelativePose(ref, src);
  const std::vector<float> depth = test::PlaneDepthMap(src, kPlaneZ);
  const ImageView full{depth.data(), src.width, src.height, src.width};
  std::vector<float> half(static_cast<size_t>(src.width / 2) * (src.height / 2));
  for (int r = 0; r < src.height / 2; ++r) {
    for (int c = 0; c < src.width / 2; ++c)
      half[r * (src.width / 2) + c] = depth[2 * r * src.width + 2 * c];
  }
  const ImageView coarse{half.data(), src.width / 2, src.height / 2, src.width / 2};
  int clamped = 0, small = 0;
  for (const ImageView& view : {full, coarse}) {
    for (int row = 3; row < ref.height; row += 17) {
      for (int col = 1; col < ref.width; col += 13) {
        for (float d : {2.0f, 2.9f, 3.0f, 3.05f, 3.4f, 5.0f, 40.0f}) {
          const float expected = ReprojectionError(ref, src, view, col, row, d, 3.0f);
          const float composed = ComposedReprojectionError(rel, src, view, col, row, d, 3.0f);
          ASSERT_NEAR(composed, expected, 1e-2f) << col << "," << row << " depth " << d;
          clamped += expected == 3.0f;
          small += expected < 0.5f;
        }
      }
    }
  }
  EXPECT_GT(clamped, 50);  // both outcomes were exercised
  EXPECT_GT(small, 50);
}

// In depth units the composed error is the depth disagreement divided by
// the unit, clamped: what the output filter's depth test measures.
TEST(GeometricCost, DepthUnitsGiveTheDepthDisagreement) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const RelativePose rel = ComputeRelativePose(ref, src);
  const std::vector<float> depth = test::PlaneDepthMap(src, kPlaneZ);
  const ImageView view{depth.data(), src.width, src.height, src.width};
  int clamped = 0, small = 0;
  for (int row = 3; row < ref.height; row += 17) {
    for (int col = 1; col < ref.width; col += 13) {
      for (float d : {2.0f, 2.95f, 3.0f, 3.03f, 3.4f, 40.0f}) {
        const float expected =
            std::min(DepthDisagreement(ref, src, view, col, row, d, 100.0f) / 0.01f, 3.0f);
        const float composed = ComposedReprojectionError(rel, src, view, col, row, d, 3.0f, 0.01f);
        ASSERT_NEAR(composed, expected, 2e-2f) << col << "," << row << " depth " << d;
        clamped += expected == 3.0f;
        small += expected < 0.5f;
      }
    }
  }
  EXPECT_GT(clamped, 20);  // both outcomes were exercised
  EXPECT_GT(small, 20);
}

// Why the geometric passes may measure depth: 2 % of depth error is worth
// 2 (pixels' worth) whatever the baseline, while the reprojection error of the
// same depth error shrinks with the baseline (a source ten times nearer the
// reference gives a tenth of the pixels), so short video baselines hardly
// pull the views' depths together.
TEST(GeometricCost, DepthUnitsDoNotShrinkWithTheBaseline) {
  const Camera ref = ReferenceCamera();
  const Camera wide =
      test::SkewedIntrinsicsCamera(200, 150, 170.0f, test::Identity(), Vec3{0.4f, 0.0f, 0.0f});
  const Camera near =
      test::SkewedIntrinsicsCamera(200, 150, 170.0f, test::Identity(), Vec3{0.04f, 0.0f, 0.0f});
  float pixels[2], depth_units[2];
  int k = 0;
  for (const Camera& src : {wide, near}) {
    const RelativePose rel = ComputeRelativePose(ref, src);
    const std::vector<float> depth = test::PlaneDepthMap(src, kPlaneZ);
    const ImageView view{depth.data(), src.width, src.height, src.width};
    pixels[k] = ComposedReprojectionError(rel, src, view, 100, 75, 1.02f * kPlaneZ, 100.0f);
    depth_units[k] =
        ComposedReprojectionError(rel, src, view, 100, 75, 1.02f * kPlaneZ, 100.0f, 0.01f);
    ++k;
  }
  EXPECT_NEAR(depth_units[0], 2.0f, 0.1f);
  EXPECT_NEAR(depth_units[1], 2.0f, 0.1f);
  EXPECT_GT(pixels[0], 0.3f);  // 2 % of a 24 px disparity
  EXPECT_LT(pixels[1], 0.2f * pixels[0]);
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// Eight depths at once, lane by lane the error of the scalar form: on and off
// the map, clamped, at another resolution, and in front of and behind the
// source camera.
TEST(GeometricCost, LanesGiveTheScalarError) {
  const Camera ref = ReferenceCamera(), src = SourceCamera();
  const RelativePose rel = ComputeRelativePose(ref, src);
  const std::vector<float> depth = test::PlaneDepthMap(src, kPlaneZ);
  std::vector<float> holed = depth;
  for (size_t i = 0; i < holed.size(); i += 3) holed[i] = 0.0f;  // no depth there
  const ImageView full{holed.data(), src.width, src.height, src.width};
  const ImageView coarse{depth.data(), src.width / 2, src.height / 2, src.width};
  const float depths[8] = {-1.0f, 2.0f, 2.9f, 3.0f, 3.05f, 3.4f, 5.0f, 40.0f};
  int clamped = 0, small = 0;
  for (const ImageView& view : {full, coarse}) {
    for (int row = 3; row < ref.height; row += 17) {
      for (int col = 1; col < ref.width; col += 13) {
        for (float unit : {0.0f, 0.01f}) {  // pixels, then depth units
          alignas(32) float lanes[8];
          _mm256_store_ps(lanes,
                          ComposedReprojectionErrorLanes(rel, src, view, col, row,
                                                         _mm256_loadu_ps(depths), 3.0f, unit));
          for (int k = 0; k < 8; ++k) {
            const float scalar =
                ComposedReprojectionError(rel, src, view, col, row, depths[k], 3.0f, unit);
            ASSERT_NEAR(lanes[k], scalar, 1e-3f) << col << "," << row << " depth " << depths[k];
            clamped += scalar == 3.0f;
            small += scalar < 0.5f;
          }
        }
      }
    }
  }
  EXPECT_GT(clamped, 50);  // both outcomes were exercised
  EXPECT_GT(small, 50);
}
#endif

}  // namespace
}  // namespace core
}  // namespace msp

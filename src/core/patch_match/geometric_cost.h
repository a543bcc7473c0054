// Geometric consistency with a source view's depth map (previous pass): the
// reference pixel's 3D point is projected into the source, lifted with the
// source's depth there and projected back; the cost is the distance between
// the pixel and where it comes back, in reference pixels.
#pragma once

#include <cmath>

#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/vec.h"
#include "core/math/warped_sample.h"

namespace msp {
namespace core {

// The source's depth at its camera pixel (u, v), from the nearest pixel of its
// map, which may be at another resolution than the camera; false when (u, v)
// is off the map or the source has no depth there.
MSP_HD bool SourceDepthAt(const Camera& src, const ImageView& src_depth, float u, float v,
                          float* depth) {
  const int c = static_cast<int>(floorf(u * src_depth.width / src.width + 0.5f));
  const int r = static_cast<int>(floorf(v * src_depth.height / src.height + 0.5f));
  if (!src_depth.Contains(c, r)) return false;
  *depth = src_depth.At(c, r);
  return *depth > 0.0f;
}

// Forward-backward reprojection error in pixels of the point at `depth` on
// the ray of reference pixel (col, row); `max_error` when the point leaves
// the source image or the source has no depth there.
MSP_HD float ReprojectionError(const Camera& ref, const Camera& src, const ImageView& src_depth,
                               int col, int row, float depth, float max_error) {
  const Vec3 X =
      CamToWorld(ref, BackProject(ref, static_cast<float>(col), static_cast<float>(row), depth));
  float u, v;
  if (!ProjectCamPoint(src, WorldToCam(src, X), &u, &v)) return max_error;
  float src_d = 0.0f;
  if (!SourceDepthAt(src, src_depth, u, v, &src_d)) return max_error;
  const Vec3 Y = CamToWorld(src, BackProject(src, u, v, src_d));
  float x, y;
  if (!ProjectCamPoint(ref, WorldToCam(ref, Y), &x, &y)) return max_error;
  const float dx = x - col, dy = y - row;
  const float error = sqrtf(dx * dx + dy * dy);
  return error < max_error ? error : max_error;
}

// Relative disagreement between the depth that the point at `depth` on the
// ray of reference pixel (col, row) has in the source and the source's own
// depth where it projects, |z - z_source| / z_source: the depth error the
// two maps' agreement bounds, the same at every baseline and resolution
// (COLMAP's fusion judges depth so, by its max_depth_error); `max_error` when
// the point leaves the source or the source has no depth there.
MSP_HD float DepthDisagreement(const Camera& ref, const Camera& src, const ImageView& src_depth,
                               int col, int row, float depth, float max_error) {
  const Vec3 X =
      CamToWorld(ref, BackProject(ref, static_cast<float>(col), static_cast<float>(row), depth));
  const Vec3 Xs = WorldToCam(src, X);
  float u, v;
  if (!ProjectCamPoint(src, Xs, &u, &v)) return max_error;
  float src_d = 0.0f;
  if (!SourceDepthAt(src, src_depth, u, v, &src_d)) return max_error;
  const float error = fabsf(Xs.z - src_d) / src_d;
  return error < max_error ? error : max_error;
}

// ReprojectionError with the two projections composed into the maps of
// `rel` (ComputeRelativePose(ref, src)): the same error, for the hot loops,
// with two divisions instead of four projections' worth of arithmetic.
// With `depth_unit` > 0 the error is the depth disagreement instead
// (DepthDisagreement) in units of `depth_unit`: 1 % of depth costs what 1 px
// does when depth_unit is 0.01, at every baseline.
MSP_HD float ComposedReprojectionError(const RelativePose& rel, const Camera& src,
                                       const ImageView& src_depth, int col, int row, float depth,
                                       float max_error, float depth_unit = 0.0f) {
  const Vec3 pixel{static_cast<float>(col), static_cast<float>(row), 1.0f};
  const Vec3 h = depth * Mul(rel.KRK, pixel) + rel.Kt;
  if (!(h.z > 0.0f)) return max_error;  // behind the source camera
  const float inv_z = 1.0f / h.z;
  const float u = h.x * inv_z, v = h.y * inv_z;
  float src_d = 0.0f;
  if (!SourceDepthAt(src, src_depth, u, v, &src_d)) return max_error;
  if (depth_unit > 0.0f) {  // h.z is the point's depth in the source camera
    const float error = fabsf(h.z - src_d) / (src_d * depth_unit);
    return error < max_error ? error : max_error;
  }
  const Vec3 q = src_d * Mul(rel.back, Vec3{u, v, 1.0f}) + rel.back_t;
  if (!(q.z > 0.0f)) return max_error;  // behind the reference camera
  const float inv_q = 1.0f / q.z;
  const float dx = q.x * inv_q - pixel.x, dy = q.y * inv_q - pixel.y;
  const float error = sqrtf(dx * dx + dy * dy);
  return error < max_error ? error : max_error;
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// ComposedReprojectionError of eight depths on the ray of pixel (col, row),
// one per lane: a hypothesis's candidates reproject into the same source
// together, and their reads of its depth map wait together.
inline __m256 ComposedReprojectionErrorLanes(const RelativePose& rel, const Camera& src,
                                             const ImageView& src_depth, int col, int row,
                                             __m256 depth, float max_error,
                                             float depth_unit = 0.0f) {
  const Vec3 ray = Mul(rel.KRK, Vec3{static_cast<float>(col), static_cast<float>(row), 1.0f});
  const __m256 hx = _mm256_fmadd_ps(depth, _mm256_set1_ps(ray.x), _mm256_set1_ps(rel.Kt.x));
  const __m256 hy = _mm256_fmadd_ps(depth, _mm256_set1_ps(ray.y), _mm256_set1_ps(rel.Kt.y));
  const __m256 hz = _mm256_fmadd_ps(depth, _mm256_set1_ps(ray.z), _mm256_set1_ps(rel.Kt.z));
  const __m256 zero = _mm256_setzero_ps();
  __m256 ok = _mm256_cmp_ps(hz, zero, _CMP_GT_OQ);  // in front of the source camera
  const __m256 inv_z = _mm256_div_ps(_mm256_set1_ps(1.0f), hz);
  const __m256 u = _mm256_mul_ps(hx, inv_z), v = _mm256_mul_ps(hy, inv_z);
  // SourceDepthAt: the nearest pixel of the map; ordered compares fail NaN.
  const __m256 half = _mm256_set1_ps(0.5f);
  const __m256 map_w = _mm256_set1_ps(static_cast<float>(src_depth.width));
  const __m256 map_h = _mm256_set1_ps(static_cast<float>(src_depth.height));
  const __m256 c = _mm256_floor_ps(_mm256_add_ps(
      _mm256_div_ps(_mm256_mul_ps(u, map_w), _mm256_set1_ps(static_cast<float>(src.width))), half));
  const __m256 r = _mm256_floor_ps(_mm256_add_ps(
      _mm256_div_ps(_mm256_mul_ps(v, map_h), _mm256_set1_ps(static_cast<float>(src.height))),
      half));
  ok = _mm256_and_ps(
      ok,
      _mm256_and_ps(
          _mm256_and_ps(_mm256_cmp_ps(c, zero, _CMP_GE_OQ), _mm256_cmp_ps(r, zero, _CMP_GE_OQ)),
          _mm256_and_ps(_mm256_cmp_ps(c, map_w, _CMP_LT_OQ), _mm256_cmp_ps(r, map_h, _CMP_LT_OQ))));
  const __m256i index =
      _mm256_add_epi32(_mm256_mullo_epi32(_mm256_cvttps_epi32(_mm256_and_ps(r, ok)),
                                          _mm256_set1_epi32(src_depth.pitch)),
                       _mm256_cvttps_epi32(_mm256_and_ps(c, ok)));
  const __m256 src_d = _mm256_mask_i32gather_ps(zero, src_depth.data, index, ok, 4);
  ok = _mm256_and_ps(ok, _mm256_cmp_ps(src_d, zero, _CMP_GT_OQ));
  const __m256 max = _mm256_set1_ps(max_error);
  if (depth_unit > 0.0f) {
    const __m256 diff = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), _mm256_sub_ps(hz, src_d));
    const __m256 error =
        _mm256_min_ps(_mm256_div_ps(diff, _mm256_mul_ps(src_d, _mm256_set1_ps(depth_unit))), max);
    return _mm256_blendv_ps(max, error, ok);
  }
  // Lifted with the source's depth and projected back into the reference.
  const Mat3& b = rel.back;
  const __m256 bx =
      _mm256_fmadd_ps(_mm256_set1_ps(b.m[0]), u,
                      _mm256_fmadd_ps(_mm256_set1_ps(b.m[1]), v, _mm256_set1_ps(b.m[2])));
  const __m256 by =
      _mm256_fmadd_ps(_mm256_set1_ps(b.m[3]), u,
                      _mm256_fmadd_ps(_mm256_set1_ps(b.m[4]), v, _mm256_set1_ps(b.m[5])));
  const __m256 bz =
      _mm256_fmadd_ps(_mm256_set1_ps(b.m[6]), u,
                      _mm256_fmadd_ps(_mm256_set1_ps(b.m[7]), v, _mm256_set1_ps(b.m[8])));
  const __m256 qx = _mm256_fmadd_ps(src_d, bx, _mm256_set1_ps(rel.back_t.x));
  const __m256 qy = _mm256_fmadd_ps(src_d, by, _mm256_set1_ps(rel.back_t.y));
  const __m256 qz = _mm256_fmadd_ps(src_d, bz, _mm256_set1_ps(rel.back_t.z));
  ok = _mm256_and_ps(ok, _mm256_cmp_ps(qz, zero, _CMP_GT_OQ));  // in front of the reference
  const __m256 inv_q = _mm256_div_ps(_mm256_set1_ps(1.0f), qz);
  const __m256 dx = _mm256_fmsub_ps(qx, inv_q, _mm256_set1_ps(static_cast<float>(col)));
  const __m256 dy = _mm256_fmsub_ps(qy, inv_q, _mm256_set1_ps(static_cast<float>(row)));
  // min() returns its second operand for NaN, as the scalar form's compare does.
  const __m256 error =
      _mm256_min_ps(_mm256_sqrt_ps(_mm256_fmadd_ps(dx, dx, _mm256_mul_ps(dy, dy))), max);
  return _mm256_blendv_ps(max, error, ok);
}
#endif

}  // namespace core
}  // namespace msp

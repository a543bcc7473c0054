// Geometric consistency with a source view's depth map (previous pass): the
// reference pixel's 3D point is projected into the source, lifted with the
// source's depth there and projected back; the cost is the distance between
// the pixel and where it comes back, in reference pixels.
#pragma once

#include <cmath>

#include "core/camera.h"
#include "core/hd.h"
#include "core/homography.h"
#include "core/image_view.h"
#include "core/vec.h"

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

// ReprojectionError with the two projections composed into the maps of
// `rel` (ComputeRelativePose(ref, src)): the same error, for the hot loops,
// with two divisions instead of four projections' worth of arithmetic.
MSP_HD float ComposedReprojectionError(const RelativePose& rel, const Camera& src,
                                       const ImageView& src_depth, int col, int row, float depth,
                                       float max_error) {
  const Vec3 pixel{static_cast<float>(col), static_cast<float>(row), 1.0f};
  const Vec3 h = depth * Mul(rel.KRK, pixel) + rel.Kt;
  if (!(h.z > 0.0f)) return max_error;  // behind the source camera
  const float inv_z = 1.0f / h.z;
  const float u = h.x * inv_z, v = h.y * inv_z;
  float src_d = 0.0f;
  if (!SourceDepthAt(src, src_depth, u, v, &src_d)) return max_error;
  const Vec3 q = src_d * Mul(rel.back, Vec3{u, v, 1.0f}) + rel.back_t;
  if (!(q.z > 0.0f)) return max_error;  // behind the reference camera
  const float inv_q = 1.0f / q.z;
  const float dx = q.x * inv_q - pixel.x, dy = q.y * inv_q - pixel.y;
  const float error = sqrtf(dx * dx + dy * dy);
  return error < max_error ? error : max_error;
}

}  // namespace core
}  // namespace msp

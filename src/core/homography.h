// Plane-induced homography from the reference to a source image (paper eq. 1):
// H = K_j (R_rel - t_rel n^T / d') K_i^-1, with (R_rel, t_rel) mapping reference
// camera coordinates to source camera coordinates.
#pragma once

#include "core/camera.h"
#include "core/hd.h"
#include "core/vec.h"

namespace msp {
namespace core {

// Pose of a source camera relative to the reference: X_src = R X_ref + t.
struct RelativePose {
  Mat3 R;
  Vec3 t;
};

MSP_HD RelativePose ComputeRelativePose(const Camera& ref, const Camera& src) {
  RelativePose rel;
  rel.R = Mul(src.R, Transposed(ref.R));
  rel.t = src.t - Mul(rel.R, ref.t);
  return rel;
}

// Homography (row-major) for the plane n^T X + dist = 0 in the reference frame.
MSP_HD Mat3 ComputeHomography(const Camera& ref, const Camera& src, const RelativePose& rel,
                              Vec3 n, float dist) {
  // A = R - t n^T / dist
  Mat3 A;
  const float inv = 1.0f / dist;
  const float tn[3] = {rel.t.x * inv, rel.t.y * inv, rel.t.z * inv};
  const float nv[3] = {n.x, n.y, n.z};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) A.m[3 * r + c] = rel.R.m[3 * r + c] - tn[r] * nv[c];
  }
  // K_src A K_ref^-1, with K^-1 = [1/fx 0 -cx/fx; 0 1/fy -cy/fy; 0 0 1].
  const Mat3 Kinv = {{1.0f / ref.fx, 0.0f, -ref.cx / ref.fx, 0.0f, 1.0f / ref.fy,
                      -ref.cy / ref.fy, 0.0f, 0.0f, 1.0f}};
  const Mat3 K = {{src.fx, 0.0f, src.cx, 0.0f, src.fy, src.cy, 0.0f, 0.0f, 1.0f}};
  return Mul(K, Mul(A, Kinv));
}

// Applies H to pixel (x, y); false when the point maps behind the source camera.
MSP_HD bool ApplyHomography(const Mat3& H, float x, float y, float* u, float* v) {
  const float w = H.m[6] * x + H.m[7] * y + H.m[8];
  if (w <= 0.0f) return false;
  const float inv = 1.0f / w;
  *u = (H.m[0] * x + H.m[1] * y + H.m[2]) * inv;
  *v = (H.m[3] * x + H.m[4] * y + H.m[5]) * inv;
  return true;
}

}  // namespace core
}  // namespace msp

// Plane-induced homography from the reference to a source image (paper eq. 1):
// H = K_j (R_rel - t_rel n^T / d') K_i^-1, with (R_rel, t_rel) mapping reference
// camera coordinates to source camera coordinates.
#pragma once

#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

// Pose of a source camera relative to the reference: X_src = R X_ref + t,
// with the parts of eq. 1 that do not depend on the plane: H = KRK - Kt m^T,
// where KRK = K_j R K_i^-1, Kt = K_j t and m = K_i^-T n / d'.
struct RelativePose {
  Mat3 R;  // reference camera frame -> source camera frame: X_src = R X_ref + t
  Vec3 t;
  Mat3 KRK;  // K_src R K_ref^-1: a reference pixel at depth d maps to d KRK [col row 1] + Kt
  Vec3 Kt;
  // The way back: a source pixel (u, v) at source depth d maps to the
  // reference pixel d back [u v 1] + back_t (homogeneous).
  Mat3 back;    // K_ref R^T K_src^-1
  Vec3 back_t;  // -K_ref R^T t
};

MSP_HD Mat3 Intrinsics(const Camera& c) {
  return Mat3{{c.fx, 0.0f, c.cx, 0.0f, c.fy, c.cy, 0.0f, 0.0f, 1.0f}};
}

MSP_HD Mat3 InverseIntrinsics(const Camera& c) {
  return Mat3{{1.0f / c.fx, 0.0f, -c.cx / c.fx, 0.0f, 1.0f / c.fy, -c.cy / c.fy, 0.0f, 0.0f, 1.0f}};
}

MSP_HD RelativePose ComputeRelativePose(const Camera& ref, const Camera& src) {
  RelativePose rel;
  rel.R = Mul(src.R, Transposed(ref.R));
  rel.t = src.t - Mul(rel.R, ref.t);
  rel.KRK = Mul(Intrinsics(src), Mul(rel.R, InverseIntrinsics(ref)));
  rel.Kt = Mul(Intrinsics(src), rel.t);
  const Mat3 KRt = Mul(Intrinsics(ref), Transposed(rel.R));
  rel.back = Mul(KRt, InverseIntrinsics(src));
  rel.back_t = -Mul(KRt, rel.t);
  return rel;
}

// The plane's part of eq. 1, m = K_i^-T n / d', shared by every source view.
struct PlaneWarp {
  float m[3];
};

MSP_HD PlaneWarp MakePlaneWarp(const Camera& ref, Vec3 n, float dist) {
  const float inv = 1.0f / dist;
  const float mx = n.x / ref.fx, my = n.y / ref.fy;
  return PlaneWarp{{mx * inv, my * inv, (n.z - mx * ref.cx - my * ref.cy) * inv}};
}

// Homography (row-major) of the plane of `warp` into the source of `rel`,
// which must come from ComputeRelativePose(ref, src).
MSP_HD Mat3 WarpHomography(const RelativePose& rel, const PlaneWarp& warp) {
  const float kt[3] = {rel.Kt.x, rel.Kt.y, rel.Kt.z};
  Mat3 H;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) H.m[3 * r + c] = rel.KRK.m[3 * r + c] - kt[r] * warp.m[c];
  }
  return H;
}

// Homography (row-major) for the plane n^T X + dist = 0 in the reference frame.
MSP_HD Mat3 ComputeHomography(const Camera& ref, const RelativePose& rel, Vec3 n, float dist) {
  return WarpHomography(rel, MakePlaneWarp(ref, n, dist));
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

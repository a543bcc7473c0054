// Pinhole cameras with exactly known geometry for the tests.
#pragma once

#include <cmath>
#include <vector>

#include "core/math/camera.h"

namespace msp {
namespace test {

inline core::Mat3 Identity() { return core::Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}}; }

// Rotation by `angle` radians about the y axis.
inline core::Mat3 RotationY(float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return core::Mat3{{c, 0, s, 0, 1, 0, -s, 0, c}};
}

// A camera with intrinsics (fx, fy, cx, cy), rotation R (world -> camera)
// and centre `center` (t = -R C).
inline core::Camera MakeCamera(int width, int height, float fx, float fy, float cx, float cy,
                               const core::Mat3& R, core::Vec3 center) {
  core::Camera cam;
  cam.width = width;
  cam.height = height;
  cam.fx = fx;
  cam.fy = fy;
  cam.cx = cx;
  cam.cy = cy;
  cam.R = R;
  cam.center = center;
  cam.t = -core::Mul(R, center);
  return cam;
}

// Focal length f, fy = 1.1 f and the principal point off the image centre,
// so that swapped axes or a dropped principal point show in the results.
inline core::Camera SkewedIntrinsicsCamera(int width, int height, float f, const core::Mat3& R,
                                           core::Vec3 center) {
  return MakeCamera(width, height, f, 1.1f * f, 0.5f * width + 1.5f, 0.5f * height - 2.0f, R,
                    center);
}

// Looking along +z from `center` (R = I), fx = fy = 0.9 width, the
// principal point at the image centre: the views of the driver tests.
inline core::Camera CentredCamera(int width, int height, core::Vec3 center = core::Vec3{0, 0, 0}) {
  return MakeCamera(width, height, 0.9f * width, 0.9f * width, 0.5f * width, 0.5f * height,
                    Identity(), center);
}

// The core math tests' pair: a 200 x 150 reference at the origin (reference
// frame = world frame) and a source 0.4 to its right, turned 0.12 rad
// towards it, both with skewed intrinsics.
inline core::Camera ReferenceCamera() {
  return SkewedIntrinsicsCamera(200, 150, 180.0f, Identity(), core::Vec3{0, 0, 0});
}

inline core::Camera SourceCamera() {
  return SkewedIntrinsicsCamera(200, 150, 170.0f, RotationY(-0.12f),
                                core::Vec3{0.4f, 0.05f, 0.02f});
}

// SourceCamera mirrored about the reference: 0.4 to its left, turned towards it.
inline core::Camera MirroredSourceCamera() {
  return SkewedIntrinsicsCamera(200, 150, 170.0f, RotationY(0.12f),
                                core::Vec3{-0.4f, -0.05f, 0.02f});
}

// The world point where the ray of pixel (col, row) of `cam` meets the
// world plane z = depth.
inline core::Vec3 PointOnPlaneZ(const core::Camera& cam, float col, float row, float depth) {
  const core::Vec3 dir = core::MulTransposed(cam.R, core::ViewRay(cam, col, row));
  return cam.center + ((depth - cam.center.z) / dir.z) * dir;
}

// The depth map of the world plane z = depth seen by `cam`.
inline std::vector<float> PlaneDepthMap(const core::Camera& cam, float depth) {
  std::vector<float> map(static_cast<size_t>(cam.width) * cam.height);
  for (int r = 0; r < cam.height; ++r) {
    for (int c = 0; c < cam.width; ++c) {
      map[r * cam.width + c] = core::WorldToCam(cam, PointOnPlaneZ(cam, c, r, depth)).z;
    }
  }
  return map;
}

}  // namespace test
}  // namespace msp

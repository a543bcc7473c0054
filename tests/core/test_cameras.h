// Cameras with exactly known geometry for the core math tests.
#pragma once

#include <cmath>

#include "core/math/camera.h"

namespace msp {
namespace core {
namespace testing_cameras {

inline Mat3 RotationY(float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return Mat3{{c, 0, s, 0, 1, 0, -s, 0, c}};
}

// Camera with rotation R (world -> camera) and centre C.
inline Camera MakeCamera(int w, int h, float f, const Mat3& R, Vec3 C) {
  Camera cam;
  cam.width = w;
  cam.height = h;
  cam.fx = f;
  cam.fy = f * 1.1f;
  cam.cx = 0.5f * w + 1.5f;
  cam.cy = 0.5f * h - 2.0f;
  cam.R = R;
  cam.center = C;
  cam.t = -Mul(R, C);
  return cam;
}

inline Camera Reference() {
  return MakeCamera(200, 150, 180.0f, Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}}, Vec3{0, 0, 0});
}

inline Camera Source() {
  return MakeCamera(200, 150, 170.0f, RotationY(-0.12f), Vec3{0.4f, 0.05f, 0.02f});
}

}  // namespace testing_cameras
}  // namespace core
}  // namespace msp

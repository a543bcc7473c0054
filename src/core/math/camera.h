// Pinhole camera as COLMAP MVS uses it: integer pixel index (col, row) is the
// image point (no +0.5), depth is camera-frame z, pose is world -> camera.
#pragma once

#include "core/math/hd.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

struct Camera {
  int width;
  int height;
  float fx, fy, cx, cy;
  Mat3 R;       // world -> camera rotation
  Vec3 t;       // world -> camera translation: X_cam = R X_world + t
  Vec3 center;  // camera centre in world coordinates, -R^T t
};

// Camera-frame point at depth z (camera z) seen through pixel (col, row).
MSP_HD Vec3 BackProject(const Camera& cam, float col, float row, float depth) {
  return Vec3{depth * (col - cam.cx) / cam.fx, depth * (row - cam.cy) / cam.fy, depth};
}

// Unnormalised viewing ray K^-1 [col, row, 1].
MSP_HD Vec3 ViewRay(const Camera& cam, float col, float row) {
  return Vec3{(col - cam.cx) / cam.fx, (row - cam.cy) / cam.fy, 1.0f};
}

// Pixel of a camera-frame point; returns false when the point is behind the camera.
MSP_HD bool ProjectCamPoint(const Camera& cam, Vec3 X, float* col, float* row) {
  if (X.z <= 0.0f) return false;
  *col = cam.fx * X.x / X.z + cam.cx;
  *row = cam.fy * X.y / X.z + cam.cy;
  return true;
}

MSP_HD Vec3 CamToWorld(const Camera& cam, Vec3 X_cam) {
  return MulTransposed(cam.R, X_cam - cam.t);
}

MSP_HD Vec3 WorldToCam(const Camera& cam, Vec3 X_world) { return Mul(cam.R, X_world) + cam.t; }

}  // namespace core
}  // namespace msp

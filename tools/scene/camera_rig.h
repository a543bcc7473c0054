// The generator's pinhole cameras (double precision, COLMAP MVS pixel
// convention: integer index (col, row) is the image point, no +0.5) and the
// rig of views around the room corner.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace msp {
namespace scene {

struct PinholeView {
  std::string name;  // image name in the workspace, e.g. "img_000.png"
  int width = 0;
  int height = 0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // world -> camera
  Eigen::Vector3d t = Eigen::Vector3d::Zero();      // X_cam = R X_world + t

  Eigen::Vector3d Center() const { return -R.transpose() * t; }
  // Camera-frame point at camera z `depth` through pixel (col, row).
  Eigen::Vector3d CameraPoint(double col, double row, double depth) const {
    return Eigen::Vector3d(depth * (col - cx) / fx, depth * (row - cy) / fy, depth);
  }
  // Unit world-space direction of the ray through pixel (col, row).
  Eigen::Vector3d RayDirection(double col, double row) const;
  // Image point and camera z of a world point; false when behind the camera.
  bool Project(const Eigen::Vector3d& X, double* col, double* row, double* z) const;
  // True when (col, row) lies on the pixel grid's extent [0, W-1] x [0, H-1].
  bool InImage(double col, double row) const {
    return col >= 0.0 && row >= 0.0 && col <= width - 1 && row <= height - 1;
  }
};

struct RigOptions {
  int width = 640;
  int height = 480;
  int num_cameras = 10;
  // The point every view looks at (with jitter): the room's is above the
  // floor near the corner, so all views share the two walls, the floor and
  // the objects.
  Eigen::Vector3d look_at = Eigen::Vector3d(1.3, 1.3, 0.6);
};

// Cameras on an arc around options.look_at, facing the corner at the origin, alternating heights
// and distances; the seed jitters positions and look-at points by centimetres.
std::vector<PinholeView> MakeCameraRig(const RigOptions& options, uint64_t seed);

// World -> camera rotation as COLMAP's (qw, qx, qy, qz), with qw >= 0.
void RotationToQuaternion(const Eigen::Matrix3d& R, double q[4]);

}  // namespace scene
}  // namespace msp

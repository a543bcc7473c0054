#include "tools/scene/camera_rig.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "tools/scene/random.h"

namespace msp {
namespace scene {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
// Horizontal field of view of every camera: a typical phone / DSLR wide lens.
constexpr double kHorizontalFovDeg = 65.0;
// The arc spans 54 degrees of azimuth around the look-at point: neighbours are
// ~6 degrees apart (plus the height changes), the end views ~55 degrees.
constexpr double kFirstAzimuthDeg = 18.0;
constexpr double kAzimuthSpanDeg = 54.0;
// Distances from the look-at point cycle through three values and heights
// alternate, so baselines are not all parallel to one line.
constexpr double kBaseDistance = 3.3;
constexpr double kDistanceStep = 0.3;
constexpr double kLowHeight = 1.35;
constexpr double kHighHeight = 1.75;
// Seeded jitter (metres) of camera centres and look-at points.
constexpr double kCenterJitter = 0.05;
constexpr double kLookAtJitter = 0.1;

double Jitter(uint64_t seed, uint64_t index, double amplitude) {
  return amplitude * (2.0 * Uniform01(seed, kStreamCameraJitter, index) - 1.0);
}

}  // namespace

Eigen::Vector3d PinholeView::RayDirection(double col, double row) const {
  const Eigen::Vector3d cam((col - cx) / fx, (row - cy) / fy, 1.0);
  return (R.transpose() * cam).normalized();
}

bool PinholeView::Project(const Eigen::Vector3d& X, double* col, double* row, double* z) const {
  const Eigen::Vector3d c = R * X + t;
  if (c.z() <= 0.0) return false;
  *col = fx * c.x() / c.z() + cx;
  *row = fy * c.y() / c.z() + cy;
  *z = c.z();
  return true;
}

std::vector<PinholeView> MakeCameraRig(const RigOptions& options, uint64_t seed) {
  std::vector<PinholeView> views;
  const int n = options.num_cameras;
  const Eigen::Vector3d& look_at = options.look_at;
  const double focal = 0.5 * options.width / std::tan(0.5 * kHorizontalFovDeg * kDegToRad);
  for (int i = 0; i < n; ++i) {
    const double s = n > 1 ? static_cast<double>(i) / (n - 1) : 0.5;
    const double azimuth = (kFirstAzimuthDeg + s * kAzimuthSpanDeg) * kDegToRad;
    const double distance = kBaseDistance + kDistanceStep * ((i % 3) - 1);
    const double height = (i % 2 == 0) ? kLowHeight : kHighHeight;
    const uint64_t key = 8 * static_cast<uint64_t>(i);
    const Eigen::Vector3d center(
        look_at.x() + distance * std::cos(azimuth) + Jitter(seed, key, kCenterJitter),
        look_at.y() + distance * std::sin(azimuth) + Jitter(seed, key + 1, kCenterJitter),
        height + Jitter(seed, key + 2, kCenterJitter));
    const Eigen::Vector3d target = look_at + Eigen::Vector3d(Jitter(seed, key + 3, kLookAtJitter),
                                                             Jitter(seed, key + 4, kLookAtJitter),
                                                             Jitter(seed, key + 5, kLookAtJitter));
    // Camera axes: x right, y down, z forward (COLMAP), world z is up.
    const Eigen::Vector3d forward = (target - center).normalized();
    const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d down = forward.cross(right);
    PinholeView view;
    char name[32];
    std::snprintf(name, sizeof(name), "img_%03d.png", i);
    view.name = name;
    view.width = options.width;
    view.height = options.height;
    view.fx = view.fy = focal;
    // What image_undistorter writes for an undistorted camera: the image centre.
    view.cx = 0.5 * options.width;
    view.cy = 0.5 * options.height;
    view.R.row(0) = right.transpose();
    view.R.row(1) = down.transpose();
    view.R.row(2) = forward.transpose();
    view.t = -view.R * center;
    views.push_back(view);
  }
  return views;
}

void RotationToQuaternion(const Eigen::Matrix3d& R, double q[4]) {
  Eigen::Quaterniond quat(R);
  quat.normalize();
  if (quat.w() < 0.0) quat.coeffs() *= -1.0;
  q[0] = quat.w();
  q[1] = quat.x();
  q[2] = quat.y();
  q[3] = quat.z();
}

}  // namespace scene
}  // namespace msp

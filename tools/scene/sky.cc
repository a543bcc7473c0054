// The sky kinds of Scene::SkyRadiance: what a ray that hits nothing sees.
#include <algorithm>
#include <cmath>

#include "tools/scene/random.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {
namespace {

// Fixed key of the cloud lattice: the clouds do not depend on --seed.
constexpr uint64_t kCloudKey = 0xC10D5;
// Clouds lie on a plane above the cameras: a direction's point there is
// (x, y) / z, in units of the cloud layer's height. Near the horizon that
// point runs off to infinity; clouds fade out below this elevation (sine).
constexpr double kMinCloudElevation = 0.03;
// Feature size of the clouds in those units: a cloud spans about a tenth of
// the image at the cameras' elevations, so an 11x11 window sees a gradient,
// not texture ("soft" clouds; fine cloud texture would be matchable, and at
// infinity any depth the sweeps can give it is wrong).
constexpr double kCloudScale = 0.35;

double SmoothStep(double t) { return t * t * (3.0 - 2.0 * t); }

// Smooth 2D value noise in [0, 1]: smoothstep weights, so no creases.
double CloudNoise(double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const int64_t ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
  const double wx = SmoothStep(x - fx), wy = SmoothStep(y - fy);
  const auto lattice = [](int64_t a, int64_t b) {
    return Uniform01(
        kCloudKey, 0,
        (static_cast<uint64_t>(a) * 73856093u) ^ (static_cast<uint64_t>(b) * 19349663u));
  };
  const double top = lattice(ix, iy) + wx * (lattice(ix + 1, iy) - lattice(ix, iy));
  const double bottom = lattice(ix, iy + 1) + wx * (lattice(ix + 1, iy + 1) - lattice(ix, iy + 1));
  return top + wy * (bottom - top);
}

// From `horizon` to `zenith` with the direction's elevation.
Eigen::Vector3d Gradient(const Eigen::Vector3d& dir, const Eigen::Vector3d& horizon,
                         const Eigen::Vector3d& zenith) {
  const double up = std::clamp(dir.z(), 0.0, 1.0);
  return horizon + (zenith - horizon) * up;
}

// Daylight blue, deeper than the bundled scene's (mean grey about 0.65 where
// the cameras look: below the bright-sky colours of docs/method.md 2.11).
Eigen::Vector3d BlueSky(const Eigen::Vector3d& dir) {
  return Gradient(dir, {0.70, 0.78, 0.92}, {0.30, 0.47, 0.86});
}

// Cover in [0, 1] of soft clouds: two octaves of smooth noise, thresholded
// softly so that clouds have clear sky between them.
double CloudCover(const Eigen::Vector3d& dir) {
  if (dir.z() <= kMinCloudElevation) return 0.0;
  const double x = dir.x() / dir.z() / kCloudScale, y = dir.y() / dir.z() / kCloudScale;
  const double v = (2.0 * CloudNoise(x, y) + CloudNoise(2.0 * x + 17.0, 2.0 * y + 5.0)) / 3.0;
  const double fade = std::min(1.0, (dir.z() - kMinCloudElevation) / kMinCloudElevation);
  return fade * SmoothStep(std::clamp((v - 0.4) / 0.3, 0.0, 1.0));
}

}  // namespace

Eigen::Vector3d Scene::SkyRadiance(const Eigen::Vector3d& dir) const {
  switch (sky) {
    case SkyKind::kPale:
      return Gradient(dir, {0.86, 0.9, 0.95}, {0.55, 0.7, 0.95});
    case SkyKind::kBlue:
      return BlueSky(dir);
    case SkyKind::kOvercast:
      return Gradient(dir, {0.88, 0.88, 0.9}, {0.72, 0.73, 0.76});
    case SkyKind::kClouds: {
      const double cover = CloudCover(dir);
      return (1.0 - cover) * BlueSky(dir) + cover * Eigen::Vector3d(0.93, 0.93, 0.95);
    }
  }
  return Eigen::Vector3d::Zero();
}

}  // namespace scene
}  // namespace msp

// Procedural reflectance and shading of the scene's materials.
#include <algorithm>
#include <cmath>

#include "tools/scene/random.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {
namespace {

constexpr double kTwoPi = 6.283185307179586;
// Odd offset so that checker / stripe boundaries never coincide with the
// object faces placed at round coordinates (which would alias into speckle).
constexpr double kPatternOffset = 0.37;
// Octaves of the fractal noise: enough fine detail for 11x11 NCC windows.
constexpr int kNoiseOctaves = 4;
// Fixed key of the noise lattice: the scene's look does not depend on --seed.
constexpr uint64_t kLatticeKey = 0x5CE7E;

double LatticeValue(int64_t x, int64_t y, int64_t z) {
  const uint64_t key = (static_cast<uint64_t>(x) * 73856093u) ^
                       (static_cast<uint64_t>(y) * 19349663u) ^
                       (static_cast<uint64_t>(z) * 83492791u);
  return Uniform01(kLatticeKey, 0, key);
}

double SmoothStep(double t) { return t * t * (3.0 - 2.0 * t); }

// Trilinear value noise in [0, 1] with smoothstep weights.
double ValueNoise(const Eigen::Vector3d& p) {
  const double fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const int64_t ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy),
                iz = static_cast<int64_t>(fz);
  const double wx = SmoothStep(p.x() - fx), wy = SmoothStep(p.y() - fy),
               wz = SmoothStep(p.z() - fz);
  double v = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const double w = (dx ? wx : 1.0 - wx) * (dy ? wy : 1.0 - wy) * (dz ? wz : 1.0 - wz);
    v += w * LatticeValue(ix + dx, iy + dy, iz + dz);
  }
  return v;
}

double FractalNoise(const Eigen::Vector3d& p) {
  double sum = 0.0, amplitude = 0.5, norm = 0.0, frequency = 1.0;
  for (int o = 0; o < kNoiseOctaves; ++o) {
    sum += amplitude * ValueNoise(frequency * p);
    norm += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return sum / norm;
}

// Smooth variation in [-1, 1] with periods of metres: the only "texture" of
// the plain surfaces, far too weak and wide for local matching windows.
double LowFrequency(const Eigen::Vector3d& p) {
  const double a = std::sin(kTwoPi * (0.8 * p.x() + 0.5 * p.y() + 0.3 * p.z()) / 1.9 + 0.4);
  const double b = std::sin(kTwoPi * (-0.3 * p.x() + 0.7 * p.y() + 0.6 * p.z()) / 3.1 + 1.3);
  return 0.5 * (a + b);
}

int FloorInt(double v) { return static_cast<int>(std::floor(v + kPatternOffset)); }

}  // namespace

Eigen::Vector3d Scene::Albedo(int material, const Eigen::Vector3d& p) const {
  const Material& m = materials[material];
  switch (m.texture) {
    case Texture::kPlain:
      return m.albedo1 * (1.0 + m.variation * LowFrequency(p));
    case Texture::kChecker:
    case Texture::kStripes:
      return Paint(material, p) == 0 ? m.albedo1 : m.albedo2;
    case Texture::kNoise: {
      const double v = FractalNoise(p / m.scale);
      // Stretch the noise's mid-range concentration towards full contrast.
      const double w = std::clamp(1.6 * (v - 0.5) + 0.5, 0.0, 1.0);
      return (1.0 - w) * m.albedo1 + w * m.albedo2;
    }
  }
  return m.albedo1;
}

int Scene::Paint(int material, const Eigen::Vector3d& p) const {
  const Material& m = materials[material];
  switch (m.texture) {
    case Texture::kChecker: {
      const int parity =
          FloorInt(p.x() / m.scale) + FloorInt(p.y() / m.scale) + FloorInt(p.z() / m.scale);
      return (parity & 1) ? 0 : 1;
    }
    case Texture::kStripes: {
      // Bands across a tilted plane family: helices on a vertical cylinder.
      const double u = p.z() + 0.5 * (p.x() + p.y());
      return (FloorInt(u / m.scale) & 1) ? 0 : 1;
    }
    case Texture::kPlain:
    case Texture::kNoise:
      break;
  }
  return 0;
}

Eigen::Vector3d Scene::Radiance(const Hit& hit) const {
  const Eigen::Vector3d to_light = (light.position - hit.point).normalized();
  const double lambert = std::max(0.0, hit.normal.dot(to_light));
  return Albedo(hit.material, hit.point) * (light.ambient + light.diffuse * lambert);
}

}  // namespace scene
}  // namespace msp

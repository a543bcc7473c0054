#include "tests/src/synthetic_views.h"

#include <cmath>
#include <string>

#include "core/math/rng.h"

namespace msp {
namespace testing_support {
namespace {

// Value noise: random values on a lattice, bilinearly interpolated, summed over
// three octaves: texture at every scale the matching window sees.
float LatticeValue(int x, int y) {
  const uint64_t h = core::Mix64((static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32) ^
                                 static_cast<uint32_t>(y));
  return static_cast<float>(h >> 40) / 16777216.0f;
}

float ValueNoise(float x, float y) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - x0, fy = y - y0;
  const float a = LatticeValue(x0, y0), b = LatticeValue(x0 + 1, y0);
  const float c = LatticeValue(x0, y0 + 1), d = LatticeValue(x0 + 1, y0 + 1);
  return (a + fx * (b - a)) + fy * ((c + fx * (d - c)) - (a + fx * (b - a)));
}

float Texture(float X, float Y) {
  constexpr float kCellsPerMetre = 60.0f;
  return 0.5f * ValueNoise(X * kCellsPerMetre, Y * kCellsPerMetre) +
         0.3f * ValueNoise(X * kCellsPerMetre * 0.37f + 11.0f, Y * kCellsPerMetre * 0.37f) +
         0.2f * ValueNoise(X * kCellsPerMetre * 0.11f, Y * kCellsPerMetre * 0.11f + 5.0f);
}

}  // namespace

core::Camera MakeTestCamera(int width, int height, core::Vec3 center) {
  core::Camera cam;
  cam.width = width;
  cam.height = height;
  cam.fx = cam.fy = 0.9f * width;
  cam.cx = 0.5f * width;
  cam.cy = 0.5f * height;
  cam.R = core::Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  cam.center = center;
  cam.t = -center;
  return cam;
}

std::vector<View> RenderFrontoParallelPlane(int width, int height, int num_views, float plane_depth,
                                            float baseline) {
  std::vector<View> views;
  for (int v = 0; v < num_views; ++v) {
    core::Vec3 center{0.0f, 0.0f, 0.0f};
    if (v > 0) {
      const float angle = 2.0f * 3.14159265f * (v - 1) / (num_views - 1);
      center = core::Vec3{baseline * std::cos(angle), baseline * std::sin(angle), 0.0f};
    }
    View view;
    view.name = "view_" + std::to_string(v) + ".png";
    view.camera = MakeTestCamera(width, height, center);
    view.gray = DenseMap(width, height, 1);
    view.color = DenseMap(width, height, 3);
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        const core::Vec3 ray =
            core::ViewRay(view.camera, static_cast<float>(c), static_cast<float>(r));
        // Camera frame is the world frame shifted by the centre (R = I).
        const float X = center.x + ray.x * plane_depth;
        const float Y = center.y + ray.y * plane_depth;
        const float g = Texture(X, Y);
        view.gray.At(r, c) = g;
        // Hue varies with the texture, so the segmenter and the CRF colour
        // term (normalised RGB) see regions.
        view.color.At(r, c, 0) = g;
        view.color.At(r, c, 1) = 1.0f - g;
        view.color.At(r, c, 2) = 0.5f;
      }
    }
    views.push_back(std::move(view));
  }
  return views;
}

}  // namespace testing_support
}  // namespace msp

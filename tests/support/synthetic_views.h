// Views of a textured fronto-parallel plane rendered analytically: the
// driver tests' and the benchmark's input.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/mvs_input.h"
#include "tests/support/cameras.h"
#include "tests/support/images.h"

namespace msp {
namespace test {

// Seed of the plane's texture.
constexpr uint64_t kViewsTextureSeed = 0;

// Grey texture at world point (X, Y) of the plane: value noise summed over
// three octaves, so the matching window sees texture at every scale.
inline float MultiScaleTexture(float X, float Y) {
  constexpr float kCellsPerMetre = 60.0f;
  const float x = X * kCellsPerMetre, y = Y * kCellsPerMetre;
  return 0.5f * ValueNoise(x, y, kViewsTextureSeed) +
         0.3f * ValueNoise(0.37f * x + 11.0f, 0.37f * y, kViewsTextureSeed) +
         0.2f * ValueNoise(0.11f * x, 0.11f * y + 5.0f, kViewsTextureSeed);
}

// `num_views` CentredCamera views (the first, the reference, at the origin
// looking down +z) of the plane z = plane_depth covered with
// MultiScaleTexture (grey, and a colour image whose hue follows the grey
// value). The sources sit on a circle of radius `baseline` in the z = 0 plane.
inline std::vector<View> RenderFrontoParallelPlane(int width, int height, int num_views,
                                                   float plane_depth, float baseline) {
  std::vector<View> views;
  for (int v = 0; v < num_views; ++v) {
    core::Vec3 center{0.0f, 0.0f, 0.0f};
    if (v > 0) {
      const float angle = 2.0f * 3.14159265f * (v - 1) / (num_views - 1);
      center = core::Vec3{baseline * std::cos(angle), baseline * std::sin(angle), 0.0f};
    }
    View view;
    view.name = "view_" + std::to_string(v) + ".png";
    view.camera = CentredCamera(width, height, center);
    view.gray = DenseMap(width, height, 1);
    view.color = DenseMap(width, height, 3);
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        const core::Vec3 X = PointOnPlaneZ(view.camera, c, r, plane_depth);
        const float g = MultiScaleTexture(X.x, X.y);
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

}  // namespace test
}  // namespace msp

// Views of a textured fronto-parallel plane rendered analytically: the
// driver tests' and the benchmark's input.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/mvs_input.h"
#include "core/patch_match/patch_match_kernel.h"
#include "engine/pixel_state.h"
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

// The PassParams of a photometric pass over `views` (views[0] the reference)
// and its pixel state: the depth range of the planes rendered here, ACMM's
// 15 view samples and the refinement's perturbations.
inline core::PassParams PhotometricPassParams(const std::vector<View>& views, PixelState* state) {
  const auto image_of = [](const View& v) {
    return core::ImageView{v.gray.data.data(), v.gray.width, v.gray.height, v.gray.width};
  };
  core::PassParams p{};
  p.ref_camera = views[0].camera;
  p.ref_image = image_of(views[0]);
  p.num_src = static_cast<int>(views.size()) - 1;
  for (int j = 0; j < p.num_src; ++j) {
    core::SourceView& src = p.src[j];
    src.camera = views[j + 1].camera;
    src.rel = core::ComputeRelativePose(p.ref_camera, src.camera);
    src.image = image_of(views[j + 1]);
    src.depth = core::ImageView{nullptr, 0, 0, 0};
  }
  p.ncc = core::NccParams{5, 2, 0, 5.0f, 0.2f};
  p.depth_min = 1.0f;
  p.depth_max = 4.0f;
  p.num_samples = 15;
  p.perturb_depth = 0.02f;
  p.perturb_normal = 0.03f;
  p.state = state->View();
  return p;
}

}  // namespace test
}  // namespace msp

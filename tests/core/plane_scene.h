// A reference and a source view of the textured world plane z = depth
// (reference frame = world frame), with the PassParams and per-pixel state of
// the core kernel, for the reliability and deformable-cost tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math/rng.h"
#include "core/patch_match/patch_match_kernel.h"
#include "tests/core/test_cameras.h"

namespace msp {
namespace core {
namespace testing_scene {

// Value noise: random values on a lattice of `cell` scene units, bilinear in between.
inline float Texture(float x, float y, float cell) {
  const float u = x / cell, v = y / cell;
  const float fu = std::floor(u), fv = std::floor(v);
  auto value = [](int i, int j) {
    return RandomUniform(Mix64(0x5EEDu), static_cast<uint32_t>((i * 7919) ^ (j * 104729)));
  };
  const int i = static_cast<int>(fu), j = static_cast<int>(fv);
  const float a = u - fu, b = v - fv;
  const float top = value(i, j) + a * (value(i + 1, j) - value(i, j));
  const float bottom = value(i, j + 1) + a * (value(i + 1, j + 1) - value(i, j + 1));
  return top + b * (bottom - top);
}

struct PlaneScene {
  Camera ref, src;
  float depth;
  std::vector<float> ref_image, src_image;
  std::vector<float> state_depth, state_normal, state_cost;
  std::vector<uint32_t> state_mask;
  PassParams params;
};

// `textured` false renders a constant image (no matching signal).
inline void Render(const Camera& cam, float depth, float cell, bool textured,
                   std::vector<float>* image) {
  image->assign(cam.width * cam.height, 0.5f);
  if (!textured) return;
  for (int r = 0; r < cam.height; ++r) {
    for (int c = 0; c < cam.width; ++c) {
      const Vec3 dir = MulTransposed(cam.R, ViewRay(cam, c, r));
      const Vec3 X = cam.center + ((depth - cam.center.z) / dir.z) * dir;
      (*image)[r * cam.width + c] = Texture(X.x, X.y, cell);
    }
  }
}

// The state holds the true plane (depth, normal -z) with view 0 selected.
inline void MakeScene(float depth, bool textured, PlaneScene* s) {
  s->ref = testing_cameras::Reference();
  s->src = testing_cameras::Source();
  s->depth = depth;
  // About 1.5 reference pixels per texture cell: matches are sharp.
  const float cell = 1.5f * depth / s->ref.fx;
  Render(s->ref, depth, cell, textured, &s->ref_image);
  Render(s->src, depth, cell, textured, &s->src_image);
  const int n = s->ref.width * s->ref.height;
  s->state_depth.assign(n, depth);
  s->state_normal.assign(3 * n, 0.0f);
  for (int i = 0; i < n; ++i) s->state_normal[2 * n + i] = -1.0f;
  s->state_cost.assign(n, kMaxCost);
  s->state_mask.assign(n, 1u);
  PassParams& p = s->params;
  p = PassParams{};
  p.ref_camera = s->ref;
  p.ref_image = ImageView{s->ref_image.data(), s->ref.width, s->ref.height, s->ref.width};
  p.num_src = 1;
  p.src[0].camera = s->src;
  p.src[0].rel = ComputeRelativePose(s->ref, s->src);
  p.src[0].image = ImageView{s->src_image.data(), s->src.width, s->src.height, s->src.width};
  p.src[0].depth = ImageView{nullptr, 0, 0, 0};
  p.ncc = NccParams{5, 2, 0, 5.0f, 0.2f};
  p.depth_min = 0.5f * depth;
  p.depth_max = 2.0f * depth;
  p.geom_lambda = 0.2f;
  p.geom_max_error = 3.0f;
  p.num_samples = 15;
  p.state = PixelStateView{s->state_depth.data(), s->state_normal.data(), s->state_cost.data(),
                           s->state_mask.data(),  s->ref.width,           s->ref.height};
}

}  // namespace testing_scene
}  // namespace core
}  // namespace msp

// A textured world plane z = depth seen by a reference camera (reference
// frame = world frame) and one or more source cameras, with the PassParams
// and the per-pixel state of the core kernel: the core tests' scene.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"
#include "tests/support/cameras.h"
#include "tests/support/images.h"

namespace msp {
namespace test {

// Seed of the plane's texture.
constexpr uint64_t kPlaneTextureSeed = 0x5EED;

struct PlaneScene {
  core::Camera ref, src;  // src: the first source view
  float depth = 0.0f;     // the plane z = depth
  float cell = 0.0f;      // texture lattice spacing, scene units
  bool textured = true;
  Image ref_image;
  std::deque<Image> src_images;  // one per source view (a deque: adding keeps them in place)
  std::vector<float> state_depth, state_normal, state_cost;
  std::vector<uint32_t> state_mask;
  core::PassParams params;
};

// The camera's image of the plane: value noise of lattice spacing s.cell on
// the plane, or a constant image (no matching signal) if not s.textured.
inline Image RenderPlane(const PlaneScene& s, const core::Camera& cam) {
  Image image = FlatImage(cam.width, cam.height, 0.5f);
  if (!s.textured) return image;
  for (int r = 0; r < cam.height; ++r) {
    for (int c = 0; c < cam.width; ++c) {
      const core::Vec3 X = PointOnPlaneZ(cam, c, r, s.depth);
      image.At(c, r) = ValueNoise(X.x / s.cell, X.y / s.cell, kPlaneTextureSeed);
    }
  }
  return image;
}

// Adds a source view of the plane seen by `cam` (no depth map); returns its index.
inline int AddSourceView(const core::Camera& cam, PlaneScene* s) {
  s->src_images.push_back(RenderPlane(*s, cam));
  const int j = s->params.num_src++;
  core::SourceView& view = s->params.src[j];
  view.camera = cam;
  view.rel = core::ComputeRelativePose(s->ref, cam);
  view.image = s->src_images.back().View();
  view.depth = core::ImageView{nullptr, 0, 0, 0};
  return j;
}

// The scene with ReferenceCamera() and SourceCamera(); the state holds the
// true plane (depth, normal -z) at every pixel with view 0 selected, and no
// cost yet (kMaxCost).
inline void MakeScene(float depth, bool textured, PlaneScene* s) {
  s->ref = ReferenceCamera();
  s->src = SourceCamera();
  s->depth = depth;
  // About 1.5 reference pixels per texture cell: matches are sharp.
  s->cell = 1.5f * depth / s->ref.fx;
  s->textured = textured;
  s->ref_image = RenderPlane(*s, s->ref);
  s->src_images.clear();
  const int n = s->ref.width * s->ref.height;
  s->state_depth.assign(n, depth);
  s->state_normal.assign(3 * n, 0.0f);
  for (int i = 0; i < n; ++i) s->state_normal[2 * n + i] = -1.0f;
  s->state_cost.assign(n, core::kMaxCost);
  s->state_mask.assign(n, 1u);
  core::PassParams& p = s->params;
  p = core::PassParams{};
  p.ref_camera = s->ref;
  p.ref_image = s->ref_image.View();
  p.num_src = 0;
  AddSourceView(s->src, s);
  p.ncc = core::NccParams{5, 2, 0, 5.0f, 0.2f};
  p.depth_min = 0.5f * depth;
  p.depth_max = 2.0f * depth;
  p.geom_lambda = 0.2f;
  p.geom_max_error = 3.0f;
  p.num_samples = 15;
  p.state =
      core::PixelStateView{s->state_depth.data(), s->state_normal.data(), s->state_cost.data(),
                           s->state_mask.data(),  s->ref.width,           s->ref.height};
}

// The conventional cost (photometric plus, in a geometric pass, geometric
// term) of h in source view j at (col, row): its entry of ViewCosts.
inline float ConventionalViewCost(const core::PassParams& p, int j, int col, int row,
                                  const core::PlaneHypothesis& h) {
  core::RefWindow w;
  core::PrepareWindow(p, col, row, &w);
  float costs[core::kMaxSourceViews];
  core::ViewCosts(p, w, h, nullptr, costs);
  return costs[j];
}

// A per-pixel mask of the state's size (PassParams::unlit, ::held) with
// only pixel (col, row) set.
inline std::vector<uint8_t> OnePixelMask(const core::PassParams& p, int col, int row) {
  std::vector<uint8_t> mask(static_cast<size_t>(p.state.width) * p.state.height, 0);
  mask[p.state.Index(col, row)] = 1;
  return mask;
}

}  // namespace test
}  // namespace msp

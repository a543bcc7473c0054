// A deformable step's test scene: a textured fronto-parallel plane seen by
// three views, whose reference pixels are reliable except for a block in the
// middle, with reliable pixels all round it so that every sector of the
// block's anchor search finds some. Shared by the deformable step's unit
// tests and the CPU/GPU parity tests.
#pragma once

#include <cstdint>
#include <vector>

#include "base/mvs_input.h"
#include "core/deformable/deformable_limits.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/prior/best_layer.h"
#include "engine/pass_schedule.h"
#include "engine/pixel_state.h"
#include "patch_match/sweeps.h"
#include "tests/support/synthetic_views.h"

namespace msp {
namespace test {

constexpr int kWidth = 64, kHeight = 48, kNumViews = 3;
constexpr float kPlaneDepth = 2.0f, kBaseline = 0.25f;
constexpr int kNumThreads = 2;
// The unreliable block of the constructed classes: reliable pixels all round,
// so every sector of its pixels' anchor search finds some.
constexpr int kBlockCol0 = 24, kBlockCol1 = 39, kBlockRow0 = 16, kBlockRow1 = 31;

inline bool InBlock(int col, int row) {
  return col >= kBlockCol0 && col <= kBlockCol1 && row >= kBlockRow0 && row <= kBlockRow1;
}

// Views of a textured fronto-parallel plane and the reference's pixel state,
// with the PassParams of a photometric pass over it.
struct BlockScene {
  std::vector<View> views =
      test::RenderFrontoParallelPlane(kWidth, kHeight, kNumViews, kPlaneDepth, kBaseline);
  PixelState state{kWidth, kHeight};
  core::PassParams params{};

  BlockScene() { params = test::PhotometricPassParams(views, &state); }

  BlockScene(const BlockScene&) = delete;
  BlockScene& operator=(const BlockScene&) = delete;

  // The true plane at every pixel, every source view selected, scored.
  void SetTruePlanes() {
    const size_t n = state.depth.size();
    for (size_t i = 0; i < n; ++i) {
      state.depth[i] = kPlaneDepth;
      state.normal[i] = state.normal[n + i] = 0.0f;
      state.normal[2 * n + i] = -1.0f;
      state.mask[i] = (1u << params.num_src) - 1u;
    }
    ScoreState(params, kNumThreads);
  }
};

// The classes a previous pass's refinement would leave: the block
// unreliable, every other pixel reliable.
inline std::vector<uint8_t> BlockClasses() {
  std::vector<uint8_t> classes(kWidth * kHeight);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      classes[row * kWidth + col] = InBlock(col, row) ? core::kUnreliable : core::kReliable;
    }
  }
  return classes;
}

constexpr int kBlockPixels = (kBlockCol1 - kBlockCol0 + 1) * (kBlockRow1 - kBlockRow0 + 1);

// A deformable pass of the first round that starts with the previous pass's classes.
inline Pass DeformablePassWithClasses() {
  Pass pass;
  pass.kind = PassKind::kGeometric;
  pass.index = 1;
  pass.start = PassStart::kPrevious;
  pass.sweeps = PassSweeps::kDeformable;
  pass.iterations = 2;
  pass.classify_after = -1;
  return pass;
}

// True when two lists of the prior's anchors name the same pixels with the
// same anchor pixels, in the same order.
inline bool SameAnchorPixels(const std::vector<core::PriorAnchors>& a,
                             const std::vector<core::PriorAnchors>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].col != b[i].col || a[i].row != b[i].row || a[i].count != b[i].count) return false;
    for (int k = 0; k < a[i].count; ++k) {
      if (a[i].cols[k] != b[i].cols[k] || a[i].rows[k] != b[i].rows[k]) return false;
    }
  }
  return true;
}

}  // namespace test
}  // namespace msp

// Per-pixel pieces of the joint-bilateral upsampling of planes at a round
// start (ACMM's multi-scale scheme after Kopf et al. 2007, "Joint Bilateral
// Upsampling"): each fine pixel weighs the planes of the coarse pixels around
// it by distance and by how alike the fine reference image is to them, and
// keeps one of those planes (src/patch_match/image_pyramid.cc runs the loop).
#pragma once

#include <cmath>

#include "core/math/hd.h"

namespace msp {
namespace core {

// The coarse pixels a fine pixel considers: the one it falls in first (it
// wins ties, so where the neighbourhood agrees the result is nearest
// neighbour's), then its 4-neighbours, then the diagonals. 3x3 suffices:
// when an edge crosses the coarse pixel a fine pixel falls in, the plane of
// the other side is held by an adjacent coarse pixel. A 5x5 window (ACMM's
// radius 2 at scale 2) adds only pixels 3.5 fine px or more away, which
// repeat the planes already in the 3x3 at 25^2 instead of 9^2 comparisons.
constexpr int kJbuNumCandidates = 9;
constexpr int kJbuOffsetCol[kJbuNumCandidates] = {0, 0, -1, 1, 0, -1, 1, -1, 1};
constexpr int kJbuOffsetRow[kJbuNumCandidates] = {0, -1, 0, 0, 1, -1, -1, 1, 1};

// Spatial sigma in fine pixels: one coarse pixel. Coarse centres lie 0.5,
// 1.5 and 2.5 fine px from a fine pixel along an axis (weights 0.97, 0.75,
// 0.46), so the guide rather than the distance decides which side of an edge
// inside the centre coarse pixel a fine pixel takes: the centre holds one
// side's plane and its grey is the mean of both sides, and the adjacent pixel
// on the fine pixel's side outvotes it from a contrast across the edge of
// ~1.8 kJbuSigmaRange. With ACMM's 0.5 coarse px (0.88, 0.32, 0.04) it takes
// ~2.8, and low-contrast edges stay where nearest neighbour puts them.
constexpr float kJbuSigmaSpatial = 2.0f;
// Range sigma on grey levels in [0, 1]: ACMM's 25.5 of 255.
constexpr float kJbuSigmaRange = 0.1f;
// Relative depth within which two candidates count as the same surface: the
// refinement's depth perturbation (2 %), so planes this close are ones the
// next pass moves between anyway.
constexpr float kJbuSameSurfaceDepth = 0.02f;

// Kopf's weight of a coarse candidate whose centre lies (dx, dy) fine pixels
// from the fine pixel, with guide difference `guide_diff` between them.
MSP_HD float JointBilateralWeight(float dx, float dy, float guide_diff) {
  return expf(-(dx * dx + dy * dy) / (2.0f * kJbuSigmaSpatial * kJbuSigmaSpatial) -
              guide_diff * guide_diff / (2.0f * kJbuSigmaRange * kJbuSigmaRange));
}

// Index of the candidate whose depth (on the fine pixel's ray) gathers the
// most weight from candidates within kJbuSameSurfaceDepth of it: a weighted
// mode. Kopf's weighted average would blend the depths of both sides of a
// depth edge into a plane on neither (a flying pixel); the mode keeps one
// side's plane, so edges stay sharp and a single plane stays exact. Ties go
// to the earlier candidate; -1 when there is none.
MSP_HD int WeightedDepthMode(const float* depth, const float* weight, int n) {
  int best = -1;
  float best_support = -1.0f;
  for (int k = 0; k < n; ++k) {
    float support = 0.0f;
    for (int j = 0; j < n; ++j) {
      if (fabsf(depth[j] - depth[k]) <= kJbuSameSurfaceDepth * depth[k]) support += weight[j];
    }
    if (support > best_support) {
      best_support = support;
      best = k;
    }
  }
  return best;
}

}  // namespace core
}  // namespace msp

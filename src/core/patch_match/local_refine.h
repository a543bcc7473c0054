// Local refinement after a pass (APD schedule): with the normal fixed, sweep
// the depth over +-PassParams::refine_radius pixels of disparity (default
// kLocalRefineRadius) and keep the best.
#pragma once

#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Mean distance from the reference centre to the centres of the views in `mask`
// (all views when the mask is empty): the baseline that turns depth into disparity.
MSP_HD float MeanBaseline(const PassParams& p, uint32_t mask) {
  float sum = 0.0f;
  int n = 0;
  for (int j = 0; j < p.num_src; ++j) {
    if (mask != 0u && !((mask >> j) & 1u)) continue;
    sum += Norm(p.src[j].camera.center - p.ref_camera.center);
    ++n;
  }
  return n > 0 ? sum / n : 0.0f;
}

// Uniform weights over the views of `mask` (all views when empty).
MSP_HD void MaskWeights(const PassParams& p, uint32_t mask, float* weights) {
  for (int j = 0; j < p.num_src; ++j) {
    weights[j] = (mask == 0u || ((mask >> j) & 1u)) ? 1.0f : 0.0f;
  }
}

// Depth at a disparity offset of `delta` pixels from depth d: disparity = f b / depth.
MSP_HD float DepthAtDisparityOffset(float focal_baseline, float depth, float delta) {
  const float disparity = focal_baseline / depth + delta;
  return disparity > 0.0f ? focal_baseline / disparity : 0.0f;
}

// Sweeps +-radius disparity pixels (LocalRefinePixel: p.refine_radius).
MSP_HD void LocalRefinePixelWithin(const PassParams& p, int col, int row, int radius) {
  const PixelStateView& s = p.state;
  const int i = s.Index(col, row);
  PlaneHypothesis cur = s.Get(i);
  if (!(cur.depth > 0.0f)) return;
  const uint32_t mask = s.mask[i];
  float weights[kMaxSourceViews];
  MaskWeights(p, mask, weights);
  const float fb = p.ref_camera.fx * MeanBaseline(p, mask);
  if (!(fb > 0.0f)) return;
  RefWindow w;
  PrepareWindow(p, col, row, &w);
  float best_cost = AggregateViewCostBelow(p, w, cur, weights, kUnboundedCost);
  PlaneHypothesis best = cur;
  for (int delta = -radius; delta <= radius; ++delta) {
    if (delta == 0) continue;
    PlaneHypothesis h = cur;
    h.depth = DepthAtDisparityOffset(fb, cur.depth, static_cast<float>(delta));
    if (!DepthInRange(p, h.depth)) continue;
    const float c = AggregateViewCostBelow(p, w, h, weights, best_cost);
    if (c < best_cost) {
      best_cost = c;
      best = h;
    }
  }
  s.Set(i, best);
  s.cost[i] = best_cost;
}

MSP_HD void LocalRefinePixel(const PassParams& p, int col, int row) {
  if (IsHeld(p, p.state.Index(col, row))) return;
  LocalRefinePixelWithin(p, col, row, p.refine_radius);
}

}  // namespace core
}  // namespace msp

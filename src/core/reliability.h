// Reliable / unreliable pixels of the APD-MVS baseline (algorithm.md 2.1):
// with the normal fixed, the view-weighted cost is sampled at 61 disparity
// offsets around the pixel's depth. A single, low, centred minimum makes the
// pixel reliable; a flat or ambiguous curve makes it unreliable, and it will
// be matched with a deformable patch over reliable anchors in the next pass.
#pragma once

#include <cstdint>

#include "core/deformable_limits.h"
#include "core/hd.h"
#include "core/local_refine.h"
#include "core/patch_match_kernel.h"

namespace msp {
namespace core {

// Allowed distance of the lowest minimum from the centre, in disparity pixels,
// per pass of a round (APD): 6 after the photometric pass, then 4, 2, 2.
constexpr int kReliabilityRadii[] = {6, 4, 2, 2};
constexpr int kNumReliabilityRadii = sizeof(kReliabilityRadii) / sizeof(kReliabilityRadii[0]);
// APD's cost thresholds (1 - NCC).
constexpr float kDefaultMaxMinimumCost = 0.5f;
constexpr float kDefaultSingleMinimumCost = 0.15f;
constexpr float kDefaultMinMinimumSpread = 0.2f;

struct ReliabilityParams {
  int radius;              // |lowest minimum - centre| allowed, in curve samples
  float max_minimum_cost;  // the lowest minimum must cost at most this
  float single_min_cost;   // with a single minimum: reliable iff its cost <= this
  float min_spread;        // with several: every other minimum must lie this far above
};

MSP_HD int ReliabilityRadius(int pass_index) {
  const int k = pass_index < 0
                    ? 0
                    : (pass_index >= kNumReliabilityRadii ? kNumReliabilityRadii - 1 : pass_index);
  return kReliabilityRadii[k];
}

MSP_HD ReliabilityParams DefaultReliabilityParams(int pass_index) {
  return ReliabilityParams{ReliabilityRadius(pass_index), kDefaultMaxMinimumCost,
                           kDefaultSingleMinimumCost, kDefaultMinMinimumSpread};
}

// True when curve[i] is a strict local minimum; an end sample is one when it
// is below its only neighbour (a competing depth at the edge of the sweep).
MSP_HD bool IsStrictLocalMinimum(const float* curve, int n, int i) {
  const bool below_left = i == 0 || curve[i] < curve[i - 1];
  const bool below_right = i == n - 1 || curve[i] < curve[i + 1];
  return n > 1 && below_left && below_right;
}

// Classifies a cost curve of n samples whose centre is sample n / 2.
MSP_HD uint8_t ClassifyCostCurve(const float* curve, int n, const ReliabilityParams& params) {
  int lowest = -1;
  int num_minima = 0;
  for (int i = 0; i < n; ++i) {
    if (!IsStrictLocalMinimum(curve, n, i)) continue;
    ++num_minima;
    if (lowest < 0 || curve[i] < curve[lowest]) lowest = i;
  }
  if (lowest < 0) return kUnreliable;  // flat curve: no minimum at all
  const int offset = lowest - n / 2;
  if (offset > params.radius || -offset > params.radius) return kUnreliable;
  if (curve[lowest] > params.max_minimum_cost) return kUnreliable;
  if (num_minima == 1) {
    return curve[lowest] <= params.single_min_cost ? kReliable : kUnreliable;
  }
  // Several minima: the lowest must stand out from the nearest competitor.
  float second = 1e30f;
  for (int i = 0; i < n; ++i) {
    if (i != lowest && IsStrictLocalMinimum(curve, n, i) && curve[i] < second) second = curve[i];
  }
  return second - curve[lowest] > params.min_spread ? kReliable : kUnreliable;
}

// Samples the curve of pixel (col, row): its normal fixed, depths at disparity
// offsets -kCurveHalfWidth..kCurveHalfWidth px (b = mean baseline to the
// selected views), each scored with uniform weights over the view mask.
// `p` should be photometric (geometric = 0): the thresholds are NCC costs.
// Writes kCurveSamples costs to `curve` and returns false when the pixel is
// "unknown": window over the border, no depth, or no selected view.
MSP_HD bool SampleCostCurve(const PassParams& p, int col, int row, float* curve) {
  const PixelStateView& s = p.state;
  const int r = p.ncc.window_radius;
  if (col < r || row < r || col + r >= s.width || row + r >= s.height) return false;
  const int i = s.Index(col, row);
  const PlaneHypothesis cur = s.Get(i);
  const uint32_t mask = s.mask[i];
  if (!(cur.depth > 0.0f) || mask == 0u) return false;
  const float fb = p.ref_camera.fx * MeanBaseline(p, mask);
  if (!(fb > 0.0f)) return false;
  float weights[kMaxSourceViews];
  float costs[kMaxSourceViews];
  MaskWeights(p, mask, weights);
  RefWindow w;
  PrepareWindow(p, col, row, &w);
  for (int k = 0; k < kCurveSamples; ++k) {
    PlaneHypothesis h = cur;
    h.depth = DepthAtDisparityOffset(fb, cur.depth, static_cast<float>(k - kCurveHalfWidth));
    if (!DepthInRange(p, h.depth)) {
      curve[k] = kMaxCost;
      continue;
    }
    ViewCosts(p, w, h, weights, costs);
    curve[k] = AggregateCost(costs, weights, p.num_src);
  }
  return true;
}

// kReliable / kUnreliable / kUnknown for pixel (col, row) after a pass.
MSP_HD uint8_t ClassifyPixel(const PassParams& p, int col, int row,
                             const ReliabilityParams& params) {
  float curve[kCurveSamples];
  if (!SampleCostCurve(p, col, row, curve)) return kUnknown;
  return ClassifyCostCurve(curve, kCurveSamples, params);
}

}  // namespace core
}  // namespace msp

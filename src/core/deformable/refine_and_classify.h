// The local refinement that ends a pass fused with the classification that
// starts the next one (APD schedule, docs/method.md sections 2.8 and 3.1). Both sweep the
// depth of the pixel's plane, normal fixed, over the same views on the same
// grid of disparity offsets: the refinement over +-kLocalRefineRadius px of
// the filtered depth, the classification over +-kCurveHalfWidth px of the
// refined depth, which lies on that grid. One lazily sampled photometric sweep
// serves both, so the refinement's samples are not computed twice; in
// geometric passes the refinement adds the geometric term to them.
#pragma once

#include <cstdint>

#include "core/deformable/reliability.h"
#include "core/math/hd.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// The samples of `sweep` from `first` on, as a curve of their own.
template <typename Sweep>
struct SweepWindow {
  Sweep* sweep;
  int first;
  MSP_HD float AtLeast(int k, float floor) { return sweep->AtLeast(first + k, floor); }
};

// The cost LocalRefinePixel gives sample k of the sweep: photometric plus,
// in geometric passes, the geometric term over the same views.
template <typename Sweep>
MSP_HD float RefinementCost(const PassParams& p, int col, int row, const CostCurveSampler& sampler,
                            Sweep* sweep, int k) {
  return sweep->At(k) + MeanGeometricTerm(p, col, row, sampler.Plane(k), sampler.weights());
}

// LocalRefinePixel, then the pixel's class (ClassifyPixel of the refined
// state) for the next pass.
MSP_HD uint8_t LocalRefineAndClassifyPixel(const PassParams& p, int col, int row,
                                           const ReliabilityParams& rp) {
  constexpr int kHalfWidth = kCurveHalfWidth + kLocalRefineRadius;
  CostCurveSampler sampler;
  if (!sampler.Prepare(p, col, row, kHalfWidth)) {
    LocalRefinePixelWithin(p, col, row, kLocalRefineRadius);
    return kUnknown;
  }
  LazyCostCurve<CostCurveSampler> sweep(&sampler, 2 * kHalfWidth + 1);
  // As LocalRefinePixel: the current depth first, then each step in range
  // that is strictly better.
  int best = kHalfWidth;
  float best_cost = RefinementCost(p, col, row, sampler, &sweep, best);
  for (int k = kHalfWidth - kLocalRefineRadius; k <= kHalfWidth + kLocalRefineRadius; ++k) {
    if (k == kHalfWidth || !DepthInRange(p, sampler.Plane(k).depth)) continue;
    const float cost = RefinementCost(p, col, row, sampler, &sweep, k);
    if (cost < best_cost) {
      best_cost = cost;
      best = k;
    }
  }
  const int i = p.state.Index(col, row);
  p.state.Set(i, sampler.Plane(best));
  p.state.cost[i] = best_cost;
  // The curve centred on the refined depth starts kCurveHalfWidth samples before it.
  SweepWindow<LazyCostCurve<CostCurveSampler>> window{&sweep, best - kCurveHalfWidth};
  LazyCostCurve<SweepWindow<LazyCostCurve<CostCurveSampler>>> curve(&window, kCurveSamples);
  return ClassifyCostCurveLazily(curve, rp);
}

}  // namespace core
}  // namespace msp

// One red-black update of an unreliable pixel with deformable patch matching
// (APD-MVS baseline, docs/method.md section 3.4): candidates are the anchors' planes
// continued to the pixel plus the anchors' RANSAC plane, views are selected
// on the anchors' candidates (8, as ACMM's propagation has), candidates are
// compared with the deformable cost (paper eq. 3), then the usual
// refinement. The stored cost is the conventional one, so that the
// neighbours' propagation keeps comparing like with like.
#pragma once

#include <cstdint>

#include "core/cost/evaluation_count.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/deformable_limits.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/math/hd.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Read-only planes of the whole image as they were when the iteration's
// anchors were found: anchors may have the pixel's colour, so reading them
// from the live state would race with their own update.
struct PlaneMapView {
  const float* depth;
  const float* normal;  // 3 planes (nx, ny, nz) of width * height
  int width;
  int height;
  MSP_HD PlaneHypothesis Get(int i) const {
    const int n = width * height;
    return PlaneHypothesis{depth[i], Vec3{normal[i], normal[n + i], normal[2 * n + i]}};
  }
};

// Candidate rows: one per anchor, the RANSAC plane, and the current plane.
constexpr int kMaxDeformableCandidates = kMaxAnchors + 2;

MSP_HD bool UsableCandidate(const PassParams& p, int col, int row, const PlaneHypothesis& h) {
  return DepthInRange(p, h.depth) && Dot(h.normal, ViewRay(p.ref_camera, static_cast<float>(col),
                                                           static_cast<float>(row))) < 0.0f;
}

// The plane a deformable update keeps so far: its deformable cost, which
// candidates must beat, and its conventional cost, the one stored.
struct Incumbent {
  PlaneHypothesis plane;
  float cost;
  float conventional_cost;
};

// h replaces the incumbent when its deformable cost in the weighted views is
// lower; its windows are scored only until it is known to lose
// (DeformableAggregateBelow).
MSP_HD void Compete(const PassParams& p, const DeformableWindows& w, const PlaneHypothesis& h,
                    const DeformableParams& d, const float* weights, Incumbent* incumbent) {
  float conventional_cost = kMaxCost;  // set whenever h wins
  const float c =
      DeformableAggregateBelow(p, w, h, d, weights, incumbent->cost, &conventional_cost);
  if (c < incumbent->cost) *incumbent = Incumbent{h, c, conventional_cost};
}

// Falls back to the conventional update when no candidate is usable. The
// anchors' candidates take their anchor windows' sums from `anchor_sums`
// (DeformableCandidateViewCosts). With a sampling solution (PixelSampling)
// the lanes sample it, after the 3D optimization when that runs, whose
// candidate competes after the RANSAC and current planes.
template <typename AnchorSumsFn>
MSP_HD void DeformableUpdatePixel(const PassParams& p, int col, int row, int iteration,
                                  const AnchorSet& anchors, const PlaneMapView& planes,
                                  const DeformableParams& d, const AnchorSumsFn& anchor_sums,
                                  const PixelSampling& sampling = PixelSampling{}) {
  MSP_EVALUATION_PHASE(kPropagationPhase);
  const PixelStateView& s = p.state;
  const int i = s.Index(col, row);
  const uint32_t pixel = static_cast<uint32_t>(i);
  PlaneHypothesis cand[kMaxDeformableCandidates];
  bool has[kMaxDeformableCandidates];
  float costs[kMaxDeformableCandidates * kMaxSourceViews];
  // The conventional costs of the same rows: the stored cost of the winner.
  float conventional[kMaxDeformableCandidates * kMaxSourceViews];
  const int num_anchors = anchors.count < kMaxAnchors ? anchors.count : kMaxAnchors;
  for (int k = 0; k < num_anchors; ++k) {
    const PlaneHypothesis h = planes.Get(planes.width * anchors.rows[k] + anchors.cols[k]);
    cand[k].normal = h.normal;
    cand[k].depth = h.depth > 0.0f ? PropagatedDepth(p.ref_camera, anchors.cols[k], anchors.rows[k],
                                                     h, col, row)
                                   : 0.0f;
    has[k] = UsableCandidate(p, col, row, cand[k]);
  }
  const int fit = num_anchors;  // the RANSAC plane
  cand[fit] = AnchorPlaneHypothesis(p.ref_camera, anchors, col, row);
  has[fit] = UsableCandidate(p, col, row, cand[fit]);
  const int current = fit + 1;
  cand[current] = s.Get(i);
  has[current] = cand[current].depth > 0.0f;
  const int num_rows = current + 1;
  bool any = false;
  for (int k = 0; k < num_rows; ++k) any = any || has[k];
  if (!any) {
    UpdatePixel(p, col, row, iteration);
    return;
  }
  DeformableWindows windows;
  PlaneHypothesis sampled;
  bool has_sampled = false;
  if (sampling.solution == nullptr) {
    PrepareDeformableWindows(p, col, row, anchors, d, &windows);
  } else {
    PrepareWindow(p, col, row, &windows.centre);
    AnchorClusters clusters;
    PatchClusters(anchors, col, row, d, &clusters);
    if (sampling.optimize) {
      has_sampled = OptimizeSampling(p, col, row, iteration, windows.centre, anchors, clusters, d,
                                     sampling.params, sampling.solution, &sampled) &&
                    UsableCandidate(p, col, row, sampled);
    }
    PrepareSampledWindows(p, anchors, clusters, d, sampling.params, pixel, *sampling.solution,
                          &windows.anchors);
  }
  // The anchors' candidates in every view: view selection reads them all.
  DeformableCandidateViewCosts(p, windows, cand, has, fit, d, anchor_sums, costs, conventional);
  Rng select_rng =
      MakeRng(RngKey(p.seed, p.image_id, p.pass_id, iteration * 4u + kStreamSelect, pixel));
  float weights[kMaxSourceViews];
  const uint32_t mask = SelectViews(costs, fit, p.num_src, kMaxSourceViews, iteration, s.mask[i],
                                    p.num_samples, &select_rng, weights);
  int best = -1;
  float best_cost = 1e30f;
  for (int k = 0; k < fit; ++k) {
    if (!has[k]) continue;
    const float c = AggregateCost(costs + k * kMaxSourceViews, weights, p.num_src);
    if (c < best_cost) {
      best_cost = c;
      best = k;
    }
  }
  Incumbent winner{best >= 0 ? cand[best] : cand[current], best_cost,
                   best >= 0
                       ? AggregateCost(conventional + best * kMaxSourceViews, weights, p.num_src)
                       : kMaxCost};
  // The RANSAC plane and the current plane only compete, after the anchors'
  // candidates (ties keep the earlier row): their selected views suffice.
  for (int k = fit; k <= current; ++k) {
    if (has[k]) Compete(p, windows, cand[k], d, weights, &winner);
  }
  if (has_sampled) Compete(p, windows, sampled, d, weights, &winner);
  MSP_EVALUATION_PHASE(kRefinementPhase);
  Rng refine_rng =
      MakeRng(RngKey(p.seed, p.image_id, p.pass_id, iteration * 4u + kStreamRefine, pixel));
  for (int k = 0; k < kNumRefinementCandidates; ++k) {
    const PlaneHypothesis h = RefinementCandidate(p, col, row, winner.plane, k, &refine_rng);
    if (DepthInRange(p, h.depth)) Compete(p, windows, h, d, weights, &winner);
  }
  s.Set(i, winner.plane);
  s.mask[i] = mask;
  // The conventional cost of the chosen plane: what neighbours compare against.
  s.cost[i] = winner.conventional_cost;
  MSP_EVALUATION_PHASE(kOtherPhase);
}

// The same with the anchor windows' sums computed on the spot.
MSP_HD void DeformableUpdatePixel(const PassParams& p, int col, int row, int iteration,
                                  const AnchorSet& anchors, const PlaneMapView& planes,
                                  const DeformableParams& d) {
  DeformableUpdatePixel(p, col, row, iteration, anchors, planes, d, DirectAnchorSums{p, d});
}

}  // namespace core
}  // namespace msp

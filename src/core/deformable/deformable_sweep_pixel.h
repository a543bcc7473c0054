// The per-pixel bodies of the deformable iterations (docs/method.md
// section 3), one pixel each, called by the CPU's row loops
// (src/deformable/deformable_sweeps.cc) and by the CUDA kernels
// (src/backend/cuda/deformable_kernels.cu) alike, so both back-ends find the same
// anchors and take the same updates.
#pragma once

#include <cstdint>

#include "core/deformable/anchor_maps.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/deformable_update.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/math/hd.h"
#include "core/math/rng.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Anchor RANSAC draws get their own streams: the seed is salted so they never
// coincide with the propagation / refinement streams of the same pixel.
constexpr uint32_t kAnchorSeedSalt = 0xA5C1D3E7u;

// The anchors of unreliable pixel (col, row) for iteration `iteration`, on
// the iteration's snapshot of the planes (maps.depth). The rays are cast in
// the first iteration and again only when a hit lost its depth; `hits` keeps
// them from one iteration to the next. With the synergistic optimization
// (`solution` not null) the first iteration also draws the pixel's sampling
// solution. True when the pixel has anchors.
MSP_HD bool FindPixelAnchors(const PassParams& p, const AnchorMaps& maps, const AnchorParams& ap,
                             int col, int row, int iteration, AnchorHits* hits, AnchorSet* anchors,
                             uint32_t* solution) {
  const uint32_t pixel = static_cast<uint32_t>(row * maps.width + col);
  Rng rng = MakeRng(RngKey(p.seed ^ kAnchorSeedSalt, p.image_id, p.pass_id, iteration, pixel));
  if (iteration == 0 && solution != nullptr) *solution = InitialSamplingSolution(p, pixel);
  if (iteration == 0 || !HitsStillValid(maps, *hits)) CastAnchorHits(maps, col, row, ap, hits);
  FitAnchors(p.ref_camera, maps, col, row, ap, *hits, &rng, anchors);
  return anchors->count > 0;
}

// One pixel of a deformable red-black sweep: the deformable update when the
// pixel has anchors (`anchors` not null, count > 0), else the conventional
// one. `sampling.solution` is the pixel's sampling solution or null.
template <typename AnchorSumsFn>
MSP_HD void DeformableSweepPixel(const PassParams& p, int col, int row, int iteration,
                                 const AnchorSet* anchors, const PlaneMapView& planes,
                                 const DeformableParams& d, const AnchorSumsFn& anchor_sums,
                                 const PixelSampling& sampling) {
  if (IsUnlit(p, p.state.Index(col, row))) return;
  if (anchors != nullptr && anchors->count > 0) {
    DeformableUpdatePixel(p, col, row, iteration, *anchors, planes, d, anchor_sums, sampling);
  } else {
    UpdatePixel(p, col, row, iteration);
  }
}

// True when the anchor windows' pairs are shared between pixels (the cached
// or own-plane sums apply): a cluster's lane, or a lane of sampled pixels,
// is no anchor's fixed window, so those modes score their lanes directly
// (DirectAnchorSums).
MSP_HD bool SharesAnchorPairs(const DeformableParams& d, bool synergistic) {
  return !(d.disassemble_clustering || synergistic);
}

// The sum of n pair costs `stride` floats apart, in window order: one
// candidate's anchor sum in one view.
MSP_HD float SumPairCosts(const float* costs, int n, int stride) {
  float total = 0.0f;
  for (int a = 0; a < n; ++a) total += costs[a * stride];
  return total;
}

// Anchor k's plane in `planes` as anchor k's own pixel sees it: the plane
// under which every pixel scores the pair (anchor k, window a), whichever
// pixel asks (CachedAnchorSums, OwnPlaneAnchorSums).
MSP_HD PreparedPlane AnchorOwnPlane(const PassParams& p, const PlaneMapView& planes,
                                    const AnchorWindows& w, int k) {
  return PreparePlane(p, w.col[k], w.row[k], planes.Get(w.row[k] * p.state.width + w.col[k]));
}

// The anchor sums of CachedAnchorSums (src/deformable/anchor_pair_cache.h)
// computed on the spot, without its cache: every pair (candidate k, window a)
// under anchor k's own plane, all windows of a candidate in one lane batch.
// A pair costs the same in any lane and batch (AnchorPairLanes), so the sums
// equal the cache's whatever it held. The CUDA back-end's provider.
struct OwnPlaneAnchorSums {
  const PassParams& p;
  const PlaneMapView& planes;
  DeformableParams d;

  MSP_HD void operator()(const AnchorWindows& w, const PreparedPlane* prepared,
                         const uint32_t* need, CandidateAnchorSums* out) const {
    const NccParams anchor_ncc = AnchorNccParams(p.ncc, d);
    const int n = w.count;
    int windows[kWindowLanes];
    for (int a = 0; a < n; ++a) windows[a] = a;
    for (int k = 0; k < n; ++k) {
      if (need[k] == 0u) continue;
      const PreparedPlane own = AnchorOwnPlane(p, planes, w, k);
      if (!own.valid) {
        DirectAnchorSums{p, d}.ForCandidate(w, prepared[k], need[k], out->sum[k]);
        continue;
      }
      PlaneWarp warps[kWindowLanes];
      for (int a = 0; a < n; ++a) warps[a] = own.warp;
      AnchorPairLanes batch;
      PrepareAnchorPairLanes(w, windows, warps, n, &batch);
      for (int j = 0; j < p.num_src; ++j) {
        if (!((need[k] >> j) & 1u)) continue;
        float costs[kWindowLanes];
        AnchorPairCosts(w, batch, p.src[j].rel, p.ref_image, p.src[j].image, anchor_ncc, costs);
        out->sum[k][j] = SumPairCosts(costs, n, 1);
      }
    }
  }
};

}  // namespace core
}  // namespace msp

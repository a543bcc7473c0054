// The matching cost of one reference window under several homographies at
// once: the candidates of a pixel update in one source view. Propagation
// scores 8 candidate planes per view, and a window's 36 samples fill 4.5
// vectors, while 8 candidates fill whole vectors exactly: sample k of all 8
// candidates is warped in one vector, each lane with its own homography. The
// sums then come out per lane with no horizontal adds, and one vector
// finishes all 8 costs, by WindowNccCost's rules (whole, partial and clipped
// windows alike). Where the build has no vector path, each lane takes
// WindowNccCost.
#pragma once

#include <cstdint>

#include "core/cost/ncc.h"
#include "core/cost/ref_window.h"
#include "core/cost/window_cost.h"
#include "core/cost/evaluation_count.h"
#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/limits.h"

namespace msp {
namespace core {

// WindowNccCost of w under H[l] for every lane l set in `lanes` (at most
// kWindowLanes); the other lanes cost kMaxCost.
MSP_HD void WindowNccCostsScalar(const RefWindow& w, const ImageView& ref, const ImageView& src,
                                 const Mat3* H, uint32_t lanes, const NccParams& p, float* costs) {
  for (int l = 0; l < kWindowLanes; ++l) {
    costs[l] = ((lanes >> l) & 1u) ? WindowNccCost(w, ref, src, H[l], p) : kMaxCost;
  }
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// Lanes outside `lanes` cost kMaxCost.
inline void ClearUnusedLanes(uint32_t lanes, float* costs) {
  for (int l = 0; l < kWindowLanes; ++l) {
    if (!((lanes >> l) & 1u)) costs[l] = kMaxCost;
  }
}

inline void WindowNccCostsAvx2(const RefWindow& w, const ImageView& ref, const ImageView& src,
                               const Mat3* H, uint32_t lanes, const NccParams& p, float* costs) {
  if (w.num_samples == 0) {
    WindowNccCostsScalar(w, ref, src, H, lanes, p, costs);
    return;
  }
  if (lanes == 0u) {
    for (int l = 0; l < kWindowLanes; ++l) costs[l] = kMaxCost;
    return;
  }
  // Lanes whose centre lands outside cost kMaxCost, whatever their samples
  // would say: drop them first, so that they neither cost their samples nor
  // keep the other lanes from the whole-box loop.
  WarpLanes warp = WarpPerLane(H, lanes, src);
  const uint32_t centred = lanes & CentreNearSourceLanes(warp, w.col, w.row);
  if (centred == 0u) {
    for (int l = 0; l < kWindowLanes; ++l) costs[l] = kMaxCost;
    return;
  }
  if (centred != lanes) {
    lanes = centred;
    warp = WarpPerLane(H, lanes, src);
  }
  // Most often every lane keeps the window's box inside the source: the
  // samples then need no tests, and the costs no reference sums or counts.
  if ((WholeBoxLanes(warp, w.box[0], w.box[1], w.box[2], w.box[3]) & lanes) == lanes) {
    __m256 sum_s = _mm256_setzero_ps(), sum_ss = _mm256_setzero_ps();
    __m256 sum_rs = _mm256_setzero_ps();
    for (int k = 0; k < w.num_samples; ++k) {
      const __m256 s =
          LoadBilinear(src, WarpCellsInside(warp, _mm256_set1_ps(w.x[k]), _mm256_set1_ps(w.y[k])));
      sum_s = _mm256_add_ps(sum_s, s);
      sum_ss = _mm256_fmadd_ps(s, s, sum_ss);
      sum_rs = _mm256_fmadd_ps(_mm256_set1_ps(w.value[k]), s, sum_rs);
    }
    const __m256 cost = w.textured ? NccFromSourceSumLanes(sum_s, sum_ss, sum_rs, w.num_samples)
                                   : _mm256_set1_ps(kMaxCost);
    _mm256_storeu_ps(costs, cost);
    ClearUnusedLanes(lanes, costs);
    return;
  }
  // The reference sums and the count serve the lanes that lose samples.
  MaskedSumLanes sums = ZeroMaskedSums();
  __m256 whole = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
  for (int k = 0; k < w.num_samples; ++k) {
    const WarpedCells cells = WarpCells(warp, _mm256_set1_ps(w.x[k]), _mm256_set1_ps(w.y[k]));
    whole = _mm256_and_ps(whole, cells.inside);
    AddMaskedSample(LoadBilinear(src, cells), _mm256_set1_ps(w.value[k]), cells.inside, &sums);
  }
  const __m256 cost = w.textured ? NccFromSourceSumLanes(sums.s, sums.ss, sums.rs, w.num_samples)
                                 : _mm256_set1_ps(kMaxCost);
  _mm256_storeu_ps(costs, cost);
  const uint32_t whole_lanes = static_cast<uint32_t>(_mm256_movemask_ps(whole));
  if ((whole_lanes & lanes) == lanes && !w.clipped) {
    ClearUnusedLanes(lanes, costs);
    return;
  }
  alignas(32) float s[kWindowLanes], ss[kWindowLanes], rs[kWindowLanes], r[kWindowLanes],
      rr[kWindowLanes], n[kWindowLanes];
  _mm256_store_ps(s, sums.s);
  _mm256_store_ps(ss, sums.ss);
  _mm256_store_ps(rs, sums.rs);
  _mm256_store_ps(r, sums.r);
  _mm256_store_ps(rr, sums.rr);
  _mm256_store_ps(n, sums.count);
  for (int l = 0; l < kWindowLanes; ++l) {
    const bool partial = !((whole_lanes >> l) & 1u);
    // WindowNccCost's rules: the centre must map into the source when the
    // window is clipped or loses samples.
    if (!((lanes >> l) & 1u) ||
        ((w.clipped || partial) && !CentreInSource(H[l], src, w.col, w.row))) {
      costs[l] = kMaxCost;
    } else if (partial) {
      const PartialSums sums{static_cast<int>(n[l]), r[l], rr[l], s[l], ss[l], rs[l]};
      costs[l] = NccFromPartialSums(sums, w.num_samples, w.spread);
    }
  }
}
#endif

MSP_HD void WindowNccCosts(const RefWindow& w, const ImageView& ref, const ImageView& src,
                           const Mat3* H, uint32_t lanes, const NccParams& p, float* costs) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  // (The scalar form counts each lane in WindowNccCost.)
  MSP_COUNT_WINDOWS(__builtin_popcount(lanes), w.num_samples);
  WindowNccCostsAvx2(w, ref, src, H, lanes, p, costs);
#else
  WindowNccCostsScalar(w, ref, src, H, lanes, p, costs);
#endif
}

}  // namespace core
}  // namespace msp

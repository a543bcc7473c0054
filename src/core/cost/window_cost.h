// The matching cost of a prepared reference window (ref_window.h): the whole
// window when its warp stays inside the source, otherwise the samples that
// do. A partial window follows GeneralNccCost's rules: the centre must land
// in the source, at least kMinValidSampleShare of the samples must, and both
// sides need texture over those samples. NCC is invariant to an affine change of
// the reference values, so the normalised values serve for any subset.
#pragma once

#include <cmath>

#include "core/cost/ncc.h"
#include "core/cost/ref_window.h"
#include "core/cost/evaluation_count.h"
#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/limits.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

// Sums over the samples of w whose bilinear support lies in the source.
struct PartialSums {
  int count;
  float r, rr, s, ss, rs;  // r: normalised reference value
};

MSP_HD PartialSums PartialWindowSumsScalar(const RefWindow& w, const ImageView& src,
                                           const Mat3& H) {
  PartialSums a = {0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  for (int k = 0; k < w.num_samples; ++k) {
    float s;
    if (!SampleWarped(src, H, w.x[k], w.y[k], &s)) continue;
    const float r = w.value[k];
    ++a.count;
    a.r += r;
    a.rr += r * r;
    a.s += s;
    a.ss += s * s;
    a.rs += r * s;
  }
  return a;
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// PartialWindowSumsScalar, eight samples at a time: lanes outside the source
// read pixel 0 and are masked out of every sum.
inline PartialSums PartialWindowSumsAvx2(const RefWindow& w, const ImageView& src, const Mat3& H) {
  const WarpLanes lanes = BroadcastWarp(H, src);
  const __m256 zero = _mm256_setzero_ps();
  __m256 sum_r = zero, sum_rr = zero, sum_s = zero, sum_ss = zero, sum_rs = zero;
  int count = 0;
  for (int k = 0; k < w.num_samples; k += kWindowLanes) {
    const WarpedCells cells = WarpCells(lanes, _mm256_loadu_ps(w.x + k), _mm256_loadu_ps(w.y + k));
    const __m256 valid = _mm256_and_ps(cells.inside, FirstLanes(w.num_samples - k));
    count += __builtin_popcount(static_cast<unsigned>(_mm256_movemask_ps(valid)));
    const __m256 s = _mm256_and_ps(LoadBilinear(src, cells), valid);
    const __m256 r = _mm256_and_ps(_mm256_loadu_ps(w.value + k), valid);
    sum_r = _mm256_add_ps(sum_r, r);
    sum_rr = _mm256_fmadd_ps(r, r, sum_rr);
    sum_s = _mm256_add_ps(sum_s, s);
    sum_ss = _mm256_fmadd_ps(s, s, sum_ss);
    sum_rs = _mm256_fmadd_ps(r, s, sum_rs);
  }
  return PartialSums{count,
                     HorizontalSum(sum_r),
                     HorizontalSum(sum_rr),
                     HorizontalSum(sum_s),
                     HorizontalSum(sum_ss),
                     HorizontalSum(sum_rs)};
}
#endif

#if defined(MSP_WINDOW_SUMS_AVX2)
// Per-lane sums over the samples whose bilinear support lies in the source,
// for vectors whose lanes are separate windows: a lane whose sample leaves
// the source (`inside` clear) reads pixel 0 instead and adds nothing.
struct MaskedSumLanes {
  __m256 s, ss, rs, r, rr, count;  // r: normalised reference value
};

inline MaskedSumLanes ZeroMaskedSums() {
  const __m256 zero = _mm256_setzero_ps();
  return MaskedSumLanes{zero, zero, zero, zero, zero, zero};
}

inline void AddMaskedSample(__m256 source, __m256 reference, __m256 inside, MaskedSumLanes* a) {
  const __m256 s = _mm256_and_ps(source, inside);
  const __m256 r = _mm256_and_ps(reference, inside);
  a->s = _mm256_add_ps(a->s, s);
  a->ss = _mm256_fmadd_ps(s, s, a->ss);
  a->rs = _mm256_fmadd_ps(r, s, a->rs);
  a->r = _mm256_add_ps(a->r, r);
  a->rr = _mm256_fmadd_ps(r, r, a->rr);
  a->count = _mm256_add_ps(a->count, _mm256_and_ps(_mm256_set1_ps(1.0f), inside));
}
#endif

MSP_HD PartialSums PartialWindowSums(const RefWindow& w, const ImageView& src, const Mat3& H) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  return PartialWindowSumsAvx2(w, src, H);
#else
  return PartialWindowSumsScalar(w, src, H);
#endif
}

// 1 - NCC over the valid samples of a partial window of `num_samples`
// samples whose raw reference values spread by `spread` (GeneralNccCost's
// rules).
MSP_HD float NccFromPartialSums(const PartialSums& a, int num_samples, float spread) {
  if (a.count == 0 || static_cast<float>(a.count) < kMinValidSampleShare * num_samples) {
    return kMaxCost;
  }
  const float n = static_cast<float>(a.count);
  const float spread_r = a.rr - a.r * a.r / n;  // in normalised units
  const float spread_s = a.ss - a.s * a.s / n;
  // The reference texture test is on raw values: `spread` scales the units.
  if (!(spread_r * spread >= kMinNccVariance * n) || !(spread_s >= kMinNccVariance * n)) {
    return kMaxCost;
  }
  const float cost = 1.0f - (a.rs - a.r * a.s / n) / sqrtf(spread_r * spread_s);
  return cost < 0.0f ? 0.0f : (cost > kMaxCost ? kMaxCost : cost);
}

// 1 - NCC in [0, 2] of window w under H, the cost the sweeps call: a window
// the fast form cannot take (num_samples 0) takes GeneralNccCost at its
// centre; the others get the same cost up to float rounding.
MSP_HD float WindowNccCost(const RefWindow& w, const ImageView& ref, const ImageView& src,
                           const Mat3& H, const NccParams& p) {
  MSP_COUNT_WINDOWS(1, w.num_samples);
  if (w.num_samples == 0) return GeneralNccCost(ref, src, H, w.col, w.row, p);
  // A whole window implies its centre maps into the source only when the
  // centre lies within its samples, which a clipped window's may not.
  if (w.clipped && !CentreInSource(H, src, w.col, w.row)) return kMaxCost;
  SourceSums sums;
  if (WholeWindowSums(w, src, H, &sums)) {
    return w.textured ? NccFromSourceSums(sums, w.num_samples) : kMaxCost;
  }
  // Part of the warped window leaves the source.
  if (!CentreInSource(H, src, w.col, w.row)) return kMaxCost;
  return NccFromPartialSums(PartialWindowSums(w, src, H), w.num_samples, w.spread);
}

}  // namespace core
}  // namespace msp

// The matching cost of a prepared reference window (ref_window.h), for every
// window inside the reference: the whole window when its warp stays inside
// the source, otherwise the samples that do. A partial window follows
// NccCost's rules: the centre must land in the source, at least
// kMinValidSampleShare of the samples must, and both sides need texture over
// those samples. NCC is invariant to an affine change of the reference values,
// so the normalised values serve for any subset.
#pragma once

#include <cmath>

#include "core/hd.h"
#include "core/homography.h"
#include "core/image_view.h"
#include "core/limits.h"
#include "core/ncc.h"
#include "core/ref_window.h"
#include "core/vec.h"

namespace msp {
namespace core {

// Sums over the samples of w whose bilinear support lies in the source.
struct PartialSums {
  int count;
  float r, rr, s, ss, rs;  // r: normalised reference value
};

MSP_HD PartialSums PartialSumsScalar(const RefWindow& w, const ImageView& src, const Mat3& H) {
  const float max_u = src.width - 1.0f, max_v = src.height - 1.0f;
  PartialSums a = {0, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  for (int k = 0; k < w.num_samples; ++k) {
    const float h2 = H.m[6] * w.x[k] + H.m[7] * w.y[k] + H.m[8];
    const float inv = 1.0f / h2;
    const float u = (H.m[0] * w.x[k] + H.m[1] * w.y[k] + H.m[2]) * inv;
    const float v = (H.m[3] * w.x[k] + H.m[4] * w.y[k] + H.m[5]) * inv;
    if (!(h2 > 0.0f && u >= 0.0f && v >= 0.0f && u < max_u && v < max_v)) continue;
    const int c0 = static_cast<int>(u), r0 = static_cast<int>(v);
    const float fx = u - c0, fy = v - r0;
    const float* p0 = src.data + r0 * src.pitch + c0;
    const float* p1 = p0 + src.pitch;
    const float top = p0[0] + fx * (p0[1] - p0[0]);
    const float bottom = p1[0] + fx * (p1[1] - p1[0]);
    const float s = top + fy * (bottom - top);
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
// PartialSumsScalar, eight samples at a time: lanes outside the source read
// pixel 0 and are masked out of every sum.
inline PartialSums PartialSumsAvx2(const RefWindow& w, const ImageView& src, const Mat3& H) {
  const __m256 h0 = _mm256_set1_ps(H.m[0]), h1 = _mm256_set1_ps(H.m[1]);
  const __m256 h2 = _mm256_set1_ps(H.m[2]), h3 = _mm256_set1_ps(H.m[3]);
  const __m256 h4 = _mm256_set1_ps(H.m[4]), h5 = _mm256_set1_ps(H.m[5]);
  const __m256 h6 = _mm256_set1_ps(H.m[6]), h7 = _mm256_set1_ps(H.m[7]);
  const __m256 h8 = _mm256_set1_ps(H.m[8]);
  const __m256i pitch = _mm256_set1_epi32(src.pitch);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256 zero = _mm256_setzero_ps();
  const __m256 max_u = _mm256_set1_ps(src.width - 1.0f), max_v = _mm256_set1_ps(src.height - 1.0f);
  __m256 sum_r = zero, sum_rr = zero, sum_s = zero, sum_ss = zero, sum_rs = zero;
  int count = 0;
  for (int k = 0; k < w.num_samples; k += kWindowLanes) {
    const __m256 x = _mm256_loadu_ps(w.x + k), y = _mm256_loadu_ps(w.y + k);
    const __m256 hw = _mm256_fmadd_ps(h6, x, _mm256_fmadd_ps(h7, y, h8));
    const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), hw);
    const __m256 u = _mm256_mul_ps(_mm256_fmadd_ps(h0, x, _mm256_fmadd_ps(h1, y, h2)), inv);
    const __m256 v = _mm256_mul_ps(_mm256_fmadd_ps(h3, x, _mm256_fmadd_ps(h4, y, h5)), inv);
    const __m256 real = _mm256_castsi256_ps(
        _mm256_cmpgt_epi32(_mm256_set1_epi32(w.num_samples - k), lane));
    const __m256 inside = _mm256_and_ps(
        _mm256_and_ps(
            _mm256_and_ps(_mm256_cmp_ps(hw, zero, _CMP_GT_OQ), _mm256_cmp_ps(u, zero, _CMP_GE_OQ)),
            _mm256_and_ps(_mm256_cmp_ps(v, zero, _CMP_GE_OQ), _mm256_cmp_ps(u, max_u, _CMP_LT_OQ))),
        _mm256_and_ps(_mm256_cmp_ps(v, max_v, _CMP_LT_OQ), real));
    count += __builtin_popcount(static_cast<unsigned>(_mm256_movemask_ps(inside)));
    const __m256 u_in = _mm256_and_ps(u, inside), v_in = _mm256_and_ps(v, inside);
    const __m256i c0 = _mm256_cvttps_epi32(u_in), r0 = _mm256_cvttps_epi32(v_in);
    const __m256 fx = _mm256_sub_ps(u_in, _mm256_cvtepi32_ps(c0));
    const __m256 fy = _mm256_sub_ps(v_in, _mm256_cvtepi32_ps(r0));
    const __m256i index = _mm256_add_epi32(_mm256_mullo_epi32(r0, pitch), c0);
    const __m256 p00 = _mm256_i32gather_ps(src.data, index, 4);
    const __m256 p01 = _mm256_i32gather_ps(src.data + 1, index, 4);
    const __m256 p10 = _mm256_i32gather_ps(src.data + src.pitch, index, 4);
    const __m256 p11 = _mm256_i32gather_ps(src.data + src.pitch + 1, index, 4);
    const __m256 top = _mm256_fmadd_ps(fx, _mm256_sub_ps(p01, p00), p00);
    const __m256 bottom = _mm256_fmadd_ps(fx, _mm256_sub_ps(p11, p10), p10);
    const __m256 s = _mm256_and_ps(_mm256_fmadd_ps(fy, _mm256_sub_ps(bottom, top), top), inside);
    const __m256 r = _mm256_and_ps(_mm256_loadu_ps(w.value + k), inside);
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

MSP_HD PartialSums PartialWindowSums(const RefWindow& w, const ImageView& src, const Mat3& H) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  return PartialSumsAvx2(w, src, H);
#else
  return PartialSumsScalar(w, src, H);
#endif
}

// 1 - NCC over the valid samples of a partial window (NccCost's rules).
MSP_HD float NccFromPartialSums(const PartialSums& a, const RefWindow& w) {
  if (a.count == 0 || static_cast<float>(a.count) < kMinValidSampleShare * w.num_samples) {
    return kMaxCost;
  }
  const float n = static_cast<float>(a.count);
  const float spread_r = a.rr - a.r * a.r / n;  // in normalised units
  const float spread_s = a.ss - a.s * a.s / n;
  // The reference texture test is on raw values: w.spread scales the units.
  if (!(spread_r * w.spread >= kMinNccVariance * n) || !(spread_s >= kMinNccVariance * n)) {
    return kMaxCost;
  }
  const float cost = 1.0f - (a.rs - a.r * a.s / n) / sqrtf(spread_r * spread_s);
  return cost < 0.0f ? 0.0f : (cost > kMaxCost ? kMaxCost : cost);
}

// 1 - NCC in [0, 2] of window w under H: the same cost as NccCost at the
// window's centre with uniform weights.
MSP_HD float WindowNccCost(const RefWindow& w, const ImageView& ref, const ImageView& src,
                           const Mat3& H, const NccParams& p) {
  if (w.num_samples == 0) return NccCost(ref, src, H, w.col, w.row, p);
  SourceSums sums;
  if (WindowSums(w, src, H, &sums)) {
    return w.textured ? NccFromSourceSums(sums, w.num_samples) : kMaxCost;
  }
  // Part of the warped window leaves the source.
  float u, v;
  if (!ApplyHomography(H, static_cast<float>(w.col), static_cast<float>(w.row), &u, &v) ||
      !(u >= 0.0f && v >= 0.0f && u <= src.width - 1.0f && v <= src.height - 1.0f)) {
    return kMaxCost;
  }
  return NccFromPartialSums(PartialWindowSums(w, src, H), w);
}

}  // namespace core
}  // namespace msp

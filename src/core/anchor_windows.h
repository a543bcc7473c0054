// The anchor windows of a deformable patch (paper eq. 3), prepared once per
// pixel update like RefWindow but laid out sample-major: entry [k][a] is
// sample k of anchor a. Scoring a hypothesis then warps sample k of all 8
// anchors in one vector, so the small 3x3 windows fill whole vectors and
// every anchor's NCC comes out of the same three sum vectors.
#pragma once

#include "core/deformable_limits.h"
#include "core/hd.h"
#include "core/image_view.h"
#include "core/ncc.h"
#include "core/ref_window.h"
#include "core/vec.h"

namespace msp {
namespace core {

// 3x3 samples at APD's step; up to 5x5 fit, larger anchor windows take the
// general path.
constexpr int kMaxAnchorWindowSamples = 25;

struct AnchorWindows {
  int count;        // anchors (lanes) in use
  int num_samples;  // per anchor window
  int radius;
  uint32_t fast;      // bit a: anchor a's window lies inside the reference
  uint32_t textured;  // bit a: its reference variance reaches kMinNccVariance
  int col[kMaxAnchors];
  int row[kMaxAnchors];
  // Lanes without a fast window (no anchor, or over the reference border)
  // sample pixel (0, 0) with value 0; their sums are ignored.
  float x[kMaxAnchorWindowSamples][kMaxAnchors];
  float y[kMaxAnchorWindowSamples][kMaxAnchors];
  float value[kMaxAnchorWindowSamples][kMaxAnchors];
};

MSP_HD void PrepareAnchorWindows(const ImageView& ref, const int* cols, const int* rows, int count,
                                 int radius, int step, AnchorWindows* w) {
  w->count = count < kMaxAnchors ? count : kMaxAnchors;
  w->radius = radius;
  w->fast = 0u;
  w->textured = 0u;
  const int per_side = 2 * radius / step + 1;
  w->num_samples = per_side * per_side <= kMaxAnchorWindowSamples ? per_side * per_side : 0;
  for (int a = 0; a < kMaxAnchors; ++a) {
    const bool used = a < w->count;
    w->col[a] = used ? cols[a] : 0;
    w->row[a] = used ? rows[a] : 0;
    const bool inside = used && w->num_samples > 0 && cols[a] - radius >= 0 &&
                        rows[a] - radius >= 0 && cols[a] + radius < ref.width &&
                        rows[a] + radius < ref.height;
    float sum = 0.0f;
    int k = 0;
    for (int oy = -radius; oy <= radius && w->num_samples > 0; oy += step) {
      for (int ox = -radius; ox <= radius; ox += step, ++k) {
        w->x[k][a] = inside ? static_cast<float>(cols[a] + ox) : 0.0f;
        w->y[k][a] = inside ? static_cast<float>(rows[a] + oy) : 0.0f;
        w->value[k][a] = inside ? ref.At(cols[a] + ox, rows[a] + oy) : 0.0f;
        sum += w->value[k][a];
      }
    }
    if (!inside) continue;
    const float mean = sum / w->num_samples;
    float sum_sq = 0.0f;
    for (k = 0; k < w->num_samples; ++k) {
      w->value[k][a] -= mean;
      sum_sq += w->value[k][a] * w->value[k][a];
    }
    w->fast |= 1u << a;
    const bool textured = sum_sq / w->num_samples >= kMinNccVariance;
    if (textured) w->textured |= 1u << a;
    const float inv_norm = textured ? 1.0f / sqrtf(sum_sq) : 0.0f;
    for (k = 0; k < w->num_samples; ++k) w->value[k][a] *= inv_norm;
  }
}

// Per-anchor source sums, and which anchors' windows were wholly inside the
// source (the others take the general NccCost).
struct AnchorSums {
  float s[kMaxAnchors], ss[kMaxAnchors], rs[kMaxAnchors];
  uint32_t inside;
};

MSP_HD void AnchorSumsScalar(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                             AnchorSums* out) {
  out->inside = 0u;
  for (int a = 0; a < kMaxAnchors; ++a) {
    out->s[a] = out->ss[a] = out->rs[a] = 0.0f;
    if (!((w.fast >> a) & 1u)) continue;
    bool inside = true;
    for (int k = 0; k < w.num_samples && inside; ++k) {
      float s;
      inside = SampleWarped(src, H, w.x[k][a], w.y[k][a], &s);
      if (!inside) break;
      out->s[a] += s;
      out->ss[a] += s * s;
      out->rs[a] += w.value[k][a] * s;
    }
    if (inside) out->inside |= 1u << a;
  }
}

#if defined(MSP_WINDOW_SUMS_AVX2)
static_assert(kMaxAnchors == kWindowLanes, "one vector lane per anchor");

// AnchorSumsScalar with sample k of the 8 anchors in one vector. A lane whose
// sample leaves the source reads pixel 0 instead and is dropped at the end.
inline void AnchorSumsAvx2(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                           AnchorSums* out) {
  const WarpLanes lanes = MakeWarpLanes(H, src);
  const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  __m256 ok = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
      _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(w.fast)), lane_bit), lane_bit));
  __m256 sum_s = _mm256_setzero_ps(), sum_ss = _mm256_setzero_ps(), sum_rs = _mm256_setzero_ps();
  for (int k = 0; k < w.num_samples; ++k) {
    const WarpedCells cells = WarpCells(lanes, _mm256_loadu_ps(w.x[k]), _mm256_loadu_ps(w.y[k]));
    ok = _mm256_and_ps(ok, cells.inside);
    const __m256 s = LoadBilinear(src, cells);
    sum_s = _mm256_add_ps(sum_s, s);
    sum_ss = _mm256_fmadd_ps(s, s, sum_ss);
    sum_rs = _mm256_fmadd_ps(_mm256_loadu_ps(w.value[k]), s, sum_rs);
  }
  _mm256_storeu_ps(out->s, sum_s);
  _mm256_storeu_ps(out->ss, sum_ss);
  _mm256_storeu_ps(out->rs, sum_rs);
  out->inside = static_cast<uint32_t>(_mm256_movemask_ps(ok));
}
#endif

MSP_HD void AnchorSumsOf(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                         AnchorSums* out) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  AnchorSumsAvx2(w, src, H, out);
#else
  AnchorSumsScalar(w, src, H, out);
#endif
}

// 1 - NCC of every anchor from its source sums (NccFromSourceSums per lane).
MSP_HD void AnchorNccCosts(const AnchorSums& sums, int num_samples, float* costs) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  const __m256 n = _mm256_set1_ps(static_cast<float>(num_samples));
  const __m256 s = _mm256_loadu_ps(sums.s), rs = _mm256_loadu_ps(sums.rs);
  const __m256 spread = _mm256_fnmadd_ps(s, _mm256_div_ps(s, n), _mm256_loadu_ps(sums.ss));
  const __m256 textured =
      _mm256_cmp_ps(spread, _mm256_mul_ps(_mm256_set1_ps(kMinNccVariance), n), _CMP_GE_OQ);
  const __m256 max_cost = _mm256_set1_ps(kMaxCost);
  __m256 cost = _mm256_sub_ps(_mm256_set1_ps(1.0f), _mm256_div_ps(rs, _mm256_sqrt_ps(spread)));
  cost = _mm256_min_ps(_mm256_max_ps(cost, _mm256_setzero_ps()), max_cost);
  // Untextured lanes (and the NaN of a negative spread) cost kMaxCost.
  _mm256_storeu_ps(costs, _mm256_blendv_ps(max_cost, cost, textured));
#else
  for (int a = 0; a < kMaxAnchors; ++a) {
    costs[a] = NccFromSourceSums(SourceSums{sums.s[a], sums.ss[a], sums.rs[a]}, num_samples);
  }
#endif
}

// Sum over the anchors of 1 - NCC of each anchor window under H; `anchor_ncc`
// (uniform weights, the anchor window's radius and step) serves the windows
// that take the general path.
MSP_HD float AnchorCostSum(const AnchorWindows& w, const ImageView& ref, const ImageView& src,
                           const Mat3& H, const NccParams& anchor_ncc) {
  AnchorSums sums;
  AnchorSumsOf(w, src, H, &sums);
  float costs[kMaxAnchors];
  AnchorNccCosts(sums, w.num_samples, costs);
  float total = 0.0f;
  for (int a = 0; a < w.count; ++a) {
    if (!((sums.inside >> a) & 1u)) {
      total += NccCost(ref, src, H, w.col[a], w.row[a], anchor_ncc);
    } else if (!((w.textured >> a) & 1u)) {
      total += kMaxCost;
    } else {
      total += costs[a];
    }
  }
  return total;
}

}  // namespace core
}  // namespace msp

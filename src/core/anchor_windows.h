// The anchor windows of a deformable patch (paper eq. 3), prepared once per
// pixel update like RefWindow but laid out sample-major: entry [k][a] is
// sample k of anchor a. Scoring a hypothesis then warps sample k of all 8
// anchors in one vector, so the small 3x3 windows fill whole vectors and
// every anchor's NCC comes out of the same sum vectors. A window that leaves
// the source in part is summed over its valid samples, as the centre window
// is (window_cost.h).
#pragma once

#include "core/deformable_limits.h"
#include "core/hd.h"
#include "core/image_view.h"
#include "core/ncc.h"
#include "core/ref_window.h"
#include "core/vec.h"
#include "core/window_cost.h"

namespace msp {
namespace core {

// 3x3 samples at APD's step; up to 5x5 fit, larger anchor windows take the
// general path.
constexpr int kMaxAnchorWindowSamples = 25;

struct AnchorWindows {
  int count;        // anchors (lanes) in use
  int num_samples;  // per anchor window
  int radius;
  uint32_t fast;              // bit a: anchor a's window lies inside the reference
  uint32_t textured;          // bit a: its reference variance reaches kMinNccVariance
  float spread[kMaxAnchors];  // sum of squared deviations of the raw reference values
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
    w->spread[a] = 0.0f;
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
    w->spread[a] = sum_sq;
    const bool textured = sum_sq / w->num_samples >= kMinNccVariance;
    if (textured) w->textured |= 1u << a;
    const float inv_norm = textured ? 1.0f / sqrtf(sum_sq) : 0.0f;
    for (k = 0; k < w->num_samples; ++k) w->value[k][a] *= inv_norm;
  }
}

// Per-anchor sums over the samples whose bilinear support lies in the
// source: the source sums of a fast window, and the reference sums and count
// that a window leaving the source in part needs (window_cost.h).
struct AnchorSums {
  float s[kMaxAnchors], ss[kMaxAnchors], rs[kMaxAnchors];
  float r[kMaxAnchors], rr[kMaxAnchors], count[kMaxAnchors];
  uint32_t inside;  // bit a: every sample of anchor a's window was valid
};

MSP_HD void AnchorSumsScalar(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                             AnchorSums* out) {
  out->inside = 0u;
  for (int a = 0; a < kMaxAnchors; ++a) {
    out->s[a] = out->ss[a] = out->rs[a] = out->r[a] = out->rr[a] = out->count[a] = 0.0f;
    if (!((w.fast >> a) & 1u)) continue;
    bool inside = true;
    for (int k = 0; k < w.num_samples; ++k) {
      float s;
      if (!SampleWarped(src, H, w.x[k][a], w.y[k][a], &s)) {
        inside = false;
        continue;
      }
      const float r = w.value[k][a];
      out->s[a] += s;
      out->ss[a] += s * s;
      out->rs[a] += r * s;
      out->r[a] += r;
      out->rr[a] += r * r;
      out->count[a] += 1.0f;
    }
    if (inside) out->inside |= 1u << a;
  }
}

#if defined(MSP_WINDOW_SUMS_AVX2)
static_assert(kMaxAnchors == kWindowLanes, "one vector lane per anchor");

// AnchorSumsScalar with sample k of the 8 anchors in one vector. A lane whose
// sample leaves the source reads pixel 0 instead, masked out of every sum.
inline void AnchorSumsAvx2(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                           AnchorSums* out) {
  const WarpLanes lanes = MakeWarpLanes(H, src);
  const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  __m256 ok = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
      _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(w.fast)), lane_bit), lane_bit));
  MaskedSumLanes sums = ZeroMaskedSums();
  for (int k = 0; k < w.num_samples; ++k) {
    const WarpedCells cells = WarpCells(lanes, _mm256_loadu_ps(w.x[k]), _mm256_loadu_ps(w.y[k]));
    ok = _mm256_and_ps(ok, cells.inside);
    AddMaskedSample(LoadBilinear(src, cells), _mm256_loadu_ps(w.value[k]), cells.inside, &sums);
  }
  _mm256_storeu_ps(out->s, sums.s);
  _mm256_storeu_ps(out->ss, sums.ss);
  _mm256_storeu_ps(out->rs, sums.rs);
  _mm256_storeu_ps(out->r, sums.r);
  _mm256_storeu_ps(out->rr, sums.rr);
  _mm256_storeu_ps(out->count, sums.count);
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
  _mm256_storeu_ps(costs, NccFromSourceSumLanes(_mm256_loadu_ps(sums.s), _mm256_loadu_ps(sums.ss),
                                                _mm256_loadu_ps(sums.rs), num_samples));
#else
  for (int a = 0; a < kMaxAnchors; ++a) {
    costs[a] = NccFromSourceSums(SourceSums{sums.s[a], sums.ss[a], sums.rs[a]}, num_samples);
  }
#endif
}

// Sum over the anchors of 1 - NCC of each anchor window under H, by
// NccCost's rules; `anchor_ncc` (uniform weights, the anchor window's radius
// and step) serves the windows over the reference border.
MSP_HD float AnchorCostSum(const AnchorWindows& w, const ImageView& ref, const ImageView& src,
                           const Mat3& H, const NccParams& anchor_ncc) {
  AnchorSums sums;
  AnchorSumsOf(w, src, H, &sums);
  float costs[kMaxAnchors];
  AnchorNccCosts(sums, w.num_samples, costs);
  float total = 0.0f;
  for (int a = 0; a < w.count; ++a) {
    if (!((w.fast >> a) & 1u)) {
      total += NccCost(ref, src, H, w.col[a], w.row[a], anchor_ncc);
    } else if ((sums.inside >> a) & 1u) {
      total += ((w.textured >> a) & 1u) ? costs[a] : kMaxCost;
    } else if (CentreInSource(H, src, w.col[a], w.row[a])) {
      const PartialSums partial{static_cast<int>(sums.count[a]),
                                sums.r[a],
                                sums.rr[a],
                                sums.s[a],
                                sums.ss[a],
                                sums.rs[a]};
      total += NccFromPartialSums(partial, w.num_samples, w.spread[a]);
    } else {
      total += kMaxCost;
    }
  }
  return total;
}

}  // namespace core
}  // namespace msp

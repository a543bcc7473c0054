// The anchor windows of a deformable patch (paper eq. 3), prepared once per
// pixel update like RefWindow but laid out sample-major: entry [k][a] is
// sample k of anchor a. Scoring a hypothesis then warps sample k of all 8
// anchors in one vector, so the small 3x3 windows fill whole vectors and
// every anchor's NCC comes out of the same sum vectors. A window that leaves
// the source in part is summed over its valid samples, as the centre window
// is (window_cost.h). Pairs of (plane, anchor window) taken from several
// hypotheses fill the lanes the same way (AnchorPairLanes).
#pragma once

#include "core/cost/ncc.h"
#include "core/cost/ref_window.h"
#include "core/cost/window_cost.h"
#include "core/deformable/deformable_limits.h"
#include "core/cost/evaluation_count.h"
#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/vec.h"

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

// Lane a's reference values at its samples w->x[k][a], w->y[k][a] (whole
// pixels), centred and scaled to unit norm when the lane is `inside` the
// reference; an outside lane keeps values 0 and is not fast.
MSP_HD void NormaliseAnchorLane(const ImageView& ref, int a, bool inside, AnchorWindows* w) {
  float sum = 0.0f;
  for (int k = 0; k < w->num_samples; ++k) {
    w->value[k][a] =
        inside ? ref.At(static_cast<int>(w->x[k][a]), static_cast<int>(w->y[k][a])) : 0.0f;
    sum += w->value[k][a];
  }
  if (!inside) return;
  const float mean = sum / w->num_samples;
  float sum_sq = 0.0f;
  for (int k = 0; k < w->num_samples; ++k) {
    w->value[k][a] -= mean;
    sum_sq += w->value[k][a] * w->value[k][a];
  }
  w->fast |= 1u << a;
  w->spread[a] = sum_sq;
  const bool textured = sum_sq / w->num_samples >= kMinNccVariance;
  if (textured) w->textured |= 1u << a;
  const float inv_norm = textured ? 1.0f / sqrtf(sum_sq) : 0.0f;
  for (int k = 0; k < w->num_samples; ++k) w->value[k][a] *= inv_norm;
}

// APD's anchor windows: lane a is the square window of `radius` and `step`
// around anchor a.
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
    int k = 0;
    for (int oy = -radius; oy <= radius && w->num_samples > 0; oy += step) {
      for (int ox = -radius; ox <= radius; ox += step, ++k) {
        w->x[k][a] = inside ? static_cast<float>(cols[a] + ox) : 0.0f;
        w->y[k][a] = inside ? static_cast<float>(rows[a] + oy) : 0.0f;
      }
    }
    NormaliseAnchorLane(ref, a, inside, w);
  }
}

// Sample pixels chosen lane by lane (disassemble-clustering: a lane holds
// the sub-patches of one anchor cluster). (col, row) is the lane's point
// for the rule that a partial window whose point leaves the source costs
// kMaxCost (AnchorWindowCost).
struct LaneSamples {
  int count;        // lanes in use
  int num_samples;  // per lane, at most kMaxAnchorWindowSamples
  int col[kMaxAnchors];
  int row[kMaxAnchors];
  int x[kMaxAnchorWindowSamples][kMaxAnchors];
  int y[kMaxAnchorWindowSamples][kMaxAnchors];
};

// The windows of explicit samples. A lane with a sample outside the
// reference is not fast, and would be scored as APD's square window of
// `radius` and `step` (anchor NccParams) around its point: samples are
// meant to lie inside.
MSP_HD void PrepareAnchorWindows(const ImageView& ref, const LaneSamples& samples, int radius,
                                 AnchorWindows* w) {
  w->count = samples.count < kMaxAnchors ? samples.count : kMaxAnchors;
  w->radius = radius;
  w->fast = 0u;
  w->textured = 0u;
  w->num_samples = samples.num_samples <= kMaxAnchorWindowSamples ? samples.num_samples
                                                                  : kMaxAnchorWindowSamples;
  for (int a = 0; a < kMaxAnchors; ++a) {
    const bool used = a < w->count;
    w->spread[a] = 0.0f;
    w->col[a] = used ? samples.col[a] : 0;
    w->row[a] = used ? samples.row[a] : 0;
    bool inside = used && w->num_samples > 0;
    for (int k = 0; k < w->num_samples && inside; ++k) {
      inside = samples.x[k][a] >= 0 && samples.y[k][a] >= 0 && samples.x[k][a] < ref.width &&
               samples.y[k][a] < ref.height;
    }
    for (int k = 0; k < w->num_samples; ++k) {
      w->x[k][a] = inside ? static_cast<float>(samples.x[k][a]) : 0.0f;
      w->y[k][a] = inside ? static_cast<float>(samples.y[k][a]) : 0.0f;
    }
    NormaliseAnchorLane(ref, a, inside, w);
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

// The sums of anchor a's window under H, into lane l of `out`.
MSP_HD void AnchorLaneSumsScalar(const AnchorWindows& w, int a, const ImageView& src, const Mat3& H,
                                 int l, AnchorSums* out) {
  out->s[l] = out->ss[l] = out->rs[l] = out->r[l] = out->rr[l] = out->count[l] = 0.0f;
  out->inside &= ~(1u << l);
  if (!((w.fast >> a) & 1u)) return;
  bool inside = true;
  for (int k = 0; k < w.num_samples; ++k) {
    float s;
    if (!SampleWarped(src, H, w.x[k][a], w.y[k][a], &s)) {
      inside = false;
      continue;
    }
    const float r = w.value[k][a];
    out->s[l] += s;
    out->ss[l] += s * s;
    out->rs[l] += r * s;
    out->r[l] += r;
    out->rr[l] += r * r;
    out->count[l] += 1.0f;
  }
  if (inside) out->inside |= 1u << l;
}

MSP_HD void AnchorSumsScalar(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                             AnchorSums* out) {
  out->inside = 0u;
  for (int a = 0; a < kMaxAnchors; ++a) AnchorLaneSumsScalar(w, a, src, H, a, out);
}

#if defined(MSP_WINDOW_SUMS_AVX2)
static_assert(kMaxAnchors == kWindowLanes, "one vector lane per anchor");

// Lane bit set where `bits` has the bit of the lane's anchor.
inline __m256 LaneBits(uint32_t bits, __m256i lane_anchor) {
  const __m256i bit = _mm256_sllv_epi32(_mm256_set1_epi32(1), lane_anchor);
  return _mm256_castsi256_ps(
      _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(bits)), bit), bit));
}

// The window sums of every lane under its warp, sample k of the lanes'
// windows at rows.x(k), rows.y(k) with reference values rows.value(k). A
// lane whose sample leaves the source reads pixel 0 instead, masked out of
// every sum; lanes outside `ok` are never inside.
template <typename Rows>
inline void AnchorSumLanes(int num_samples, const Rows& rows, const WarpLanes& lanes, __m256 ok,
                           const ImageView& src, AnchorSums* out) {
  MaskedSumLanes sums = ZeroMaskedSums();
  for (int k = 0; k < num_samples; ++k) {
    const WarpedCells cells = WarpCells(lanes, rows.x(k), rows.y(k));
    ok = _mm256_and_ps(ok, cells.inside);
    AddMaskedSample(LoadBilinear(src, cells), rows.value(k), cells.inside, &sums);
  }
  _mm256_storeu_ps(out->s, sums.s);
  _mm256_storeu_ps(out->ss, sums.ss);
  _mm256_storeu_ps(out->rs, sums.rs);
  _mm256_storeu_ps(out->r, sums.r);
  _mm256_storeu_ps(out->rr, sums.rr);
  _mm256_storeu_ps(out->count, sums.count);
  out->inside = static_cast<uint32_t>(_mm256_movemask_ps(ok));
}

// Lane a is anchor a.
struct AnchorRows {
  const AnchorWindows& w;
  __m256 x(int k) const { return _mm256_loadu_ps(w.x[k]); }
  __m256 y(int k) const { return _mm256_loadu_ps(w.y[k]); }
  __m256 value(int k) const { return _mm256_loadu_ps(w.value[k]); }
};

// AnchorSumsScalar with sample k of the 8 anchors in one vector.
inline void AnchorSumsAvx2(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                           AnchorSums* out) {
  const __m256i identity = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  AnchorSumLanes(w.num_samples, AnchorRows{w}, BroadcastWarp(H, src), LaneBits(w.fast, identity),
                 src, out);
}
#endif

MSP_HD void AnchorSumsOf(const AnchorWindows& w, const ImageView& src, const Mat3& H,
                         AnchorSums* out) {
  MSP_COUNT_ANCHOR_WINDOWS(w.count, w.num_samples);
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

// 1 - NCC of anchor a's window by GeneralNccCost's rules, from lane l of the
// window sums and of their fast costs. `homography()` gives the lane's H;
// it is called only for a window that leaves the source or the reference,
// whose rules need it. `anchor_ncc` (uniform weights, the anchor window's
// radius and step) serves the windows over the reference border.
template <typename HomographyFn>
MSP_HD float AnchorWindowCost(const AnchorWindows& w, int a, const AnchorSums& sums, int l,
                              float fast_cost, const ImageView& ref, const ImageView& src,
                              const NccParams& anchor_ncc, HomographyFn homography) {
  if (!((w.fast >> a) & 1u)) {
    return GeneralNccCost(ref, src, homography(), w.col[a], w.row[a], anchor_ncc);
  }
  if ((sums.inside >> l) & 1u) return ((w.textured >> a) & 1u) ? fast_cost : kMaxCost;
  const Mat3 H = homography();
  if (!CentreInSource(H, src, w.col[a], w.row[a])) return kMaxCost;
  const PartialSums partial{
      static_cast<int>(sums.count[l]), sums.r[l], sums.rr[l], sums.s[l], sums.ss[l], sums.rs[l]};
  return NccFromPartialSums(partial, w.num_samples, w.spread[a]);
}

// Sum over the anchors of 1 - NCC of each anchor window under H.
MSP_HD float AnchorCostSum(const AnchorWindows& w, const ImageView& ref, const ImageView& src,
                           const Mat3& H, const NccParams& anchor_ncc) {
  AnchorSums sums;
  AnchorSumsOf(w, src, H, &sums);
  float costs[kMaxAnchors];
  AnchorNccCosts(sums, w.num_samples, costs);
  float total = 0.0f;
  for (int a = 0; a < w.count; ++a) {
    total += AnchorWindowCost(w, a, sums, a, costs[a], ref, src, anchor_ncc, [&] { return H; });
  }
  return total;
}

// Up to kWindowLanes (plane, anchor window) pairs, scored together: lane l
// warps the window of anchor `anchor[l]` with the plane of `warp[l]`. A pair
// costs the same in any lane and beside any other pairs (every lane's
// arithmetic is its own), which lets pairs computed apart stand in for each
// other exactly. Prepared once for all source views.
struct AnchorPairLanes {
  int count;
  int anchor[kWindowLanes];  // spare lanes repeat lane 0
  PlaneWarp warp[kWindowLanes];
#if defined(MSP_WINDOW_SUMS_AVX2)
  __m256 m[3];  // the warps' m, a lane each
  __m256 fast;  // lanes whose anchor has a fast window
  __m256 x[kMaxAnchorWindowSamples], y[kMaxAnchorWindowSamples],
      value[kMaxAnchorWindowSamples];  // the lanes' windows, sample-major
#endif
};

MSP_HD void PrepareAnchorPairLanes(const AnchorWindows& w, const int* anchor, const PlaneWarp* warp,
                                   int count, AnchorPairLanes* out) {
  out->count = count;
  for (int l = 0; l < kWindowLanes; ++l) {
    const int from = l < count ? l : 0;
    out->anchor[l] = anchor[from];
    out->warp[l] = warp[from];
  }
#if defined(MSP_WINDOW_SUMS_AVX2)
  // Built from the values, not reloaded from the arrays just written: a
  // vector load of fresh scalar stores stalls.
  const int* a = out->anchor;
  const __m256i index = _mm256_setr_epi32(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]);
  for (int c = 0; c < 3; ++c) {
    const PlaneWarp* v = out->warp;
    out->m[c] = _mm256_setr_ps(v[0].m[c], v[1].m[c], v[2].m[c], v[3].m[c], v[4].m[c], v[5].m[c],
                               v[6].m[c], v[7].m[c]);
  }
  out->fast = LaneBits(w.fast, index);
  for (int k = 0; k < w.num_samples; ++k) {
    out->x[k] = _mm256_permutevar8x32_ps(_mm256_loadu_ps(w.x[k]), index);
    out->y[k] = _mm256_permutevar8x32_ps(_mm256_loadu_ps(w.y[k]), index);
    out->value[k] = _mm256_permutevar8x32_ps(_mm256_loadu_ps(w.value[k]), index);
  }
#else
  (void)w;  // the scalar path reads the windows through the lanes' anchors
#endif
}

// 1 - NCC of every prepared pair in the source of `rel` (anchor windows'
// rules, AnchorWindowCost), into costs[0 .. lanes.count).
MSP_HD void AnchorPairCosts(const AnchorWindows& w, const AnchorPairLanes& lanes,
                            const RelativePose& rel, const ImageView& ref, const ImageView& src,
                            const NccParams& anchor_ncc, float* costs) {
  MSP_COUNT_ANCHOR_WINDOWS(lanes.count, w.num_samples);
#if defined(MSP_WINDOW_SUMS_AVX2)
  // H = KRK - Kt m^T per lane (WarpHomography with the planes in lanes).
  WarpLanes warp = BroadcastWarp(rel.KRK, src);
  const float kt[3] = {rel.Kt.x, rel.Kt.y, rel.Kt.z};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      warp.h[3 * r + c] = _mm256_fnmadd_ps(_mm256_set1_ps(kt[r]), lanes.m[c], warp.h[3 * r + c]);
    }
  }
  struct PairRows {
    const AnchorPairLanes& lanes;
    __m256 x(int k) const { return lanes.x[k]; }
    __m256 y(int k) const { return lanes.y[k]; }
    __m256 value(int k) const { return lanes.value[k]; }
  };
  AnchorSums sums;
  AnchorSumLanes(w.num_samples, PairRows{lanes}, warp, lanes.fast, src, &sums);
  float fast[kWindowLanes];
  AnchorNccCosts(sums, w.num_samples, fast);
  for (int l = 0; l < lanes.count; ++l) {
    costs[l] = AnchorWindowCost(w, lanes.anchor[l], sums, l, fast[l], ref, src, anchor_ncc, [&] {
      Mat3 H;
      for (int i = 0; i < 9; ++i) {
        float h[kWindowLanes];
        _mm256_storeu_ps(h, warp.h[i]);
        H.m[i] = h[l];
      }
      return H;
    });
  }
#else
  for (int l = 0; l < lanes.count; ++l) {
    const int a = lanes.anchor[l];
    const Mat3 H = WarpHomography(rel, lanes.warp[l]);
    AnchorSums sums;
    sums.inside = 0u;
    AnchorLaneSumsScalar(w, a, src, H, 0, &sums);
    const float fast =
        NccFromSourceSums(SourceSums{sums.s[0], sums.ss[0], sums.rs[0]}, w.num_samples);
    costs[l] = AnchorWindowCost(w, a, sums, 0, fast, ref, src, anchor_ncc, [&] { return H; });
  }
#endif
}

}  // namespace core
}  // namespace msp

// The fast form of the matching cost. A pixel is scored against many planes
// and views (9 candidates x all views, then refinement), and the reference
// side of NCC is the same every time, so it is prepared once per window: the
// sample positions and the reference intensities normalised to zero mean and
// unit norm. A cost then needs only three source sums:
//   NCC = sum(r^ s) / sqrt(sum(s^2) - sum(s)^2 / n).
// Windows the fast form cannot take (bilateral weights, too many samples) use
// GeneralNccCost (ncc.h); windows whose warp leaves the source in part are
// summed over their valid samples (window_cost.h). A window over the reference
// border keeps the samples inside the reference, as GeneralNccCost does. Both
// forms give the same cost up to float rounding.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/cost/ncc.h"
#include "core/math/hd.h"
#include "core/math/image_view.h"
#include "core/math/limits.h"
#include "core/math/vec.h"
#include "core/math/warped_sample.h"

namespace msp {
namespace core {

// Lanes of the vector path; windows are padded to a multiple of it.
constexpr int kWindowLanes = 8;
// 11x11 at step 2 is 36 samples; larger windows take the general path.
constexpr int kMaxFastWindowSamples = 64;

struct RefWindow {
  int col;  // window centre in the reference image
  int row;
  int radius;
  int num_samples;  // 0: the window takes GeneralNccCost
  int clipped;      // the window crosses the reference border: only its samples inside remain
  int textured;     // reference variance reaches kMinNccVariance
  float spread;     // sum of squared deviations of the raw reference values
  // The box holding every sample and the centre: x0, x1, y0, y1. A warp
  // that keeps it inside the source keeps every sample there.
  float box[4];
  // Sample positions and normalised reference values; lanes from num_samples
  // up to the next multiple of kWindowLanes repeat the centre with value 0.
  float x[kMaxFastWindowSamples];
  float y[kMaxFastWindowSamples];
  float value[kMaxFastWindowSamples];
};

MSP_HD int PaddedSamples(int n) { return (n + kWindowLanes - 1) / kWindowLanes * kWindowLanes; }

// A window keeps only the samples of its centre's region when the region
// holds at least this share of them; fewer are too few to match, and the
// region is a sliver there: the whole window is its best evidence.
constexpr int kMinRegionSampleQuarters = 1;

// The region of the window's centre in `regions` (a label per reference
// pixel, 0 = unlabelled), or 0 when the window keeps every sample: no
// regions, an unlabelled centre, a region that fills the window, or one that
// holds less than a quarter of it (kMinRegionSampleQuarters).
MSP_HD int32_t WindowRegion(const ImageView& ref, const int32_t* regions, int col, int row,
                            int radius, int step) {
  if (regions == nullptr) return 0;
  const int32_t centre = regions[row * ref.width + col];
  if (centre == 0) return 0;
  int total = 0, outside = 0;
  for (int r = row - radius; r <= row + radius; r += step) {
    for (int c = col - radius; c <= col + radius; c += step) {
      if (c < 0 || r < 0 || c >= ref.width || r >= ref.height) continue;
      const int32_t label = regions[r * ref.width + c];
      ++total;
      outside += label != 0 && label != centre;
    }
  }
  const int inside = total - outside;
  return outside > 0 && 4 * inside >= kMinRegionSampleQuarters * total ? centre : 0;
}

// Prepares the window of `radius` and `step` at (col, row). With `regions`
// (null: none), a window keeps only the samples that share its centre's
// region or are unlabelled (WindowRegion): a window that reaches across a
// region edge into another surface's texture is no evidence for the centre.
MSP_HD void PrepareRefWindow(const ImageView& ref, int col, int row, int radius, int step,
                             int bilateral, const int32_t* regions, RefWindow* w) {
  w->col = col;
  w->row = row;
  w->radius = radius;
  w->num_samples = 0;
  w->textured = 1;
  const int per_side = 2 * radius / step + 1;
  w->clipped = !(col - radius >= 0 && row - radius >= 0 && col + radius < ref.width &&
                 row + radius < ref.height);
  if (bilateral || per_side * per_side > kMaxFastWindowSamples) return;
  const int32_t region = WindowRegion(ref, regions, col, row, radius, step);
  // A window cut to its region is partial, as one cut by the image border.
  if (region != 0) w->clipped = 1;
  // The box starts at the centre, which the padding lanes repeat. Integer
  // bounds: fminf and fmaxf are library calls here, not instructions.
  int box_c0 = col, box_c1 = col, box_r0 = row, box_r1 = row;
  int n = 0;
  float sum = 0.0f;
  for (int oy = -radius; oy <= radius; oy += step) {
    for (int ox = -radius; ox <= radius; ox += step) {
      const int c = col + ox, r = row + oy;
      if (c < 0 || r < 0 || c >= ref.width || r >= ref.height) continue;
      if (region != 0) {
        const int32_t label = regions[r * ref.width + c];
        if (label != 0 && label != region) continue;
      }
      w->x[n] = static_cast<float>(c);
      w->y[n] = static_cast<float>(r);
      w->value[n] = ref.At(c, r);
      sum += w->value[n];
      box_c0 = c < box_c0 ? c : box_c0;
      box_c1 = c > box_c1 ? c : box_c1;
      box_r0 = r < box_r0 ? r : box_r0;
      box_r1 = r > box_r1 ? r : box_r1;
      ++n;
    }
  }
  if (n == 0) return;  // a reference smaller than the window's step
  const float mean = sum / n;
  float sum_sq = 0.0f;
  for (int k = 0; k < n; ++k) {
    w->value[k] -= mean;
    sum_sq += w->value[k] * w->value[k];
  }
  w->num_samples = n;
  w->spread = sum_sq;
  w->textured = sum_sq / n >= kMinNccVariance;
  const float inv_norm = w->textured ? 1.0f / sqrtf(sum_sq) : 0.0f;
  for (int k = 0; k < n; ++k) w->value[k] *= inv_norm;
  for (int k = n; k < PaddedSamples(n); ++k) {
    w->x[k] = static_cast<float>(col);
    w->y[k] = static_cast<float>(row);
    w->value[k] = 0.0f;
  }
  w->box[0] = static_cast<float>(box_c0);
  w->box[1] = static_cast<float>(box_c1);
  w->box[2] = static_cast<float>(box_r0);
  w->box[3] = static_cast<float>(box_r1);
}

// Source sums over window w warped by H.
struct SourceSums {
  float s, ss, rs;
};

// The sums when every sample's bilinear support lies inside the source
// (SampleWarped); false as soon as one does not, and the window then takes
// the partial form (window_cost.h).
MSP_HD bool WholeWindowSumsScalar(const RefWindow& w, const ImageView& src, const Mat3& H,
                                  SourceSums* out) {
  SourceSums sums = {0.0f, 0.0f, 0.0f};
  for (int k = 0; k < w.num_samples; ++k) {
    float s;
    if (!SampleWarped(src, H, w.x[k], w.y[k], &s)) return false;
    sums.s += s;
    sums.ss += s * s;
    sums.rs += w.value[k] * s;
  }
  *out = sums;
  return true;
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// WholeWindowSumsScalar, eight samples at a time; padding lanes are masked out.
// When the warp keeps the window's box inside the source, no sample needs
// its own test.
inline bool WholeWindowSumsAvx2(const RefWindow& w, const ImageView& src, const Mat3& H,
                                SourceSums* out) {
  const WarpLanes lanes = BroadcastWarp(H, src);
  const bool whole = WholeBox(lanes, w.box[0], w.box[1], w.box[2], w.box[3]);
  __m256 sum_s = _mm256_setzero_ps(), sum_ss = _mm256_setzero_ps(), sum_rs = _mm256_setzero_ps();
  for (int k = 0; k < w.num_samples; k += kWindowLanes) {
    const __m256 x = _mm256_loadu_ps(w.x + k), y = _mm256_loadu_ps(w.y + k);
    WarpedCells cells;
    if (whole) {
      cells = WarpCellsInside(lanes, x, y);
    } else {
      cells = WarpCells(lanes, x, y);
      if (_mm256_movemask_ps(cells.inside) != 0xFF) return false;
    }
    const __m256 s = _mm256_and_ps(LoadBilinear(src, cells), FirstLanes(w.num_samples - k));
    sum_s = _mm256_add_ps(sum_s, s);
    sum_ss = _mm256_fmadd_ps(s, s, sum_ss);
    sum_rs = _mm256_fmadd_ps(_mm256_loadu_ps(w.value + k), s, sum_rs);
  }
  *out = SourceSums{HorizontalSum(sum_s), HorizontalSum(sum_ss), HorizontalSum(sum_rs)};
  return true;
}
#endif

MSP_HD bool WholeWindowSums(const RefWindow& w, const ImageView& src, const Mat3& H,
                            SourceSums* out) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  return WholeWindowSumsAvx2(w, src, H, out);
#else
  return WholeWindowSumsScalar(w, src, H, out);
#endif
}

// 1 - NCC from the source sums of a fast window.
MSP_HD float NccFromSourceSums(const SourceSums& a, int n) {
  const float mean = a.s / n;
  const float spread = a.ss - a.s * mean;  // n * variance
  if (!(spread >= kMinNccVariance * n)) return kMaxCost;
  const float cost = 1.0f - a.rs / sqrtf(spread);
  // Rounding can leave |NCC| a hair above 1.
  return cost < 0.0f ? 0.0f : (cost > kMaxCost ? kMaxCost : cost);
}

#if defined(MSP_WINDOW_SUMS_AVX2)
// NccFromSourceSums of eight windows at once, one per lane.
inline __m256 NccFromSourceSumLanes(__m256 s, __m256 ss, __m256 rs, int num_samples) {
  const __m256 n = _mm256_set1_ps(static_cast<float>(num_samples));
  const __m256 spread = _mm256_fnmadd_ps(s, _mm256_div_ps(s, n), ss);
  const __m256 textured =
      _mm256_cmp_ps(spread, _mm256_mul_ps(_mm256_set1_ps(kMinNccVariance), n), _CMP_GE_OQ);
  const __m256 max_cost = _mm256_set1_ps(kMaxCost);
  __m256 cost = _mm256_sub_ps(_mm256_set1_ps(1.0f), _mm256_div_ps(rs, _mm256_sqrt_ps(spread)));
  cost = _mm256_min_ps(_mm256_max_ps(cost, _mm256_setzero_ps()), max_cost);
  // Untextured lanes (and the NaN of a negative spread) cost kMaxCost.
  return _mm256_blendv_ps(max_cost, cost, textured);
}
#endif

}  // namespace core
}  // namespace msp

// The fast form of the matching cost. A pixel is scored against many planes
// and views (9 candidates x all views, then refinement), and the reference
// side of NCC is the same every time, so it is prepared once per window: the
// sample positions and the reference intensities normalised to zero mean and
// unit norm. A cost then needs only three source sums:
//   NCC = sum(r^ s) / sqrt(sum(s^2) - sum(s)^2 / n).
// Windows the fast form cannot take (image border, bilateral weights, too many
// samples) use the general NccCost; windows whose warp leaves the source in
// part are summed over their valid samples (window_cost.h). Both forms give
// the same cost up to float rounding.
#pragma once

#include <cmath>

#include "core/hd.h"
#include "core/image_view.h"
#include "core/limits.h"
#include "core/ncc.h"
#include "core/vec.h"

#if defined(__AVX2__) && defined(__FMA__) && !defined(__CUDACC__)
#define MSP_WINDOW_SUMS_AVX2 1
#include <immintrin.h>
#endif

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
  int num_samples;  // 0: the window takes the general NccCost
  int textured;     // reference variance reaches kMinNccVariance
  float spread;     // sum of squared deviations of the raw reference values
  // Sample positions and normalised reference values; lanes from num_samples
  // up to the next multiple of kWindowLanes repeat the centre with value 0.
  float x[kMaxFastWindowSamples];
  float y[kMaxFastWindowSamples];
  float value[kMaxFastWindowSamples];
};

MSP_HD int PaddedSamples(int n) { return (n + kWindowLanes - 1) / kWindowLanes * kWindowLanes; }

// Prepares the window of `radius` and `step` at (col, row).
MSP_HD void PrepareRefWindow(const ImageView& ref, int col, int row, int radius, int step,
                             int bilateral, RefWindow* w) {
  w->col = col;
  w->row = row;
  w->radius = radius;
  w->num_samples = 0;
  w->textured = 1;
  const int per_side = 2 * radius / step + 1;
  const bool inside = col - radius >= 0 && row - radius >= 0 && col + radius < ref.width &&
                      row + radius < ref.height;
  if (bilateral || !inside || per_side * per_side > kMaxFastWindowSamples) return;
  int n = 0;
  float sum = 0.0f;
  for (int oy = -radius; oy <= radius; oy += step) {
    for (int ox = -radius; ox <= radius; ox += step, ++n) {
      w->x[n] = static_cast<float>(col + ox);
      w->y[n] = static_cast<float>(row + oy);
      w->value[n] = ref.At(col + ox, row + oy);
      sum += w->value[n];
    }
  }
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
}

// Source sums over window w warped by H.
struct SourceSums {
  float s, ss, rs;
};

// The sums when every sample's 2x2 bilinear support lies inside the source
// (0 <= u < width - 1, 0 <= v < height - 1, in front of the camera); false as
// soon as one does not, and the window then takes the general path.
MSP_HD bool WindowSumsScalar(const RefWindow& w, const ImageView& src, const Mat3& H,
                             SourceSums* out) {
  const float max_u = src.width - 1.0f, max_v = src.height - 1.0f;
  SourceSums sums = {0.0f, 0.0f, 0.0f};
  for (int k = 0; k < w.num_samples; ++k) {
    const float h2 = H.m[6] * w.x[k] + H.m[7] * w.y[k] + H.m[8];
    const float inv = 1.0f / h2;
    const float u = (H.m[0] * w.x[k] + H.m[1] * w.y[k] + H.m[2]) * inv;
    const float v = (H.m[3] * w.x[k] + H.m[4] * w.y[k] + H.m[5]) * inv;
    if (!(h2 > 0.0f && u >= 0.0f && v >= 0.0f && u < max_u && v < max_v)) return false;
    const int c0 = static_cast<int>(u), r0 = static_cast<int>(v);
    const float fx = u - c0, fy = v - r0;
    const float* p0 = src.data + r0 * src.pitch + c0;
    const float* p1 = p0 + src.pitch;
    const float top = p0[0] + fx * (p0[1] - p0[0]);
    const float bottom = p1[0] + fx * (p1[1] - p1[0]);
    const float s = top + fy * (bottom - top);
    sums.s += s;
    sums.ss += s * s;
    sums.rs += w.value[k] * s;
  }
  *out = sums;
  return true;
}

#if defined(MSP_WINDOW_SUMS_AVX2)
inline float HorizontalSum(__m256 v) {
  const __m128 lo = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  const __m128 pairs = _mm_add_ps(lo, _mm_movehl_ps(lo, lo));
  return _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, 1)));
}

// WindowSumsScalar, eight samples at a time. The two taps of a bilinear row
// are adjacent, so each row is one 64-bit gather of four samples' pairs; the
// index lanes are pre-ordered so that de-interleaving the pairs puts samples
// back in lane order. Padding lanes are masked out of the source sums.
inline bool WindowSumsAvx2(const RefWindow& w, const ImageView& src, const Mat3& H,
                           SourceSums* out) {
  const __m256 h0 = _mm256_set1_ps(H.m[0]), h1 = _mm256_set1_ps(H.m[1]);
  const __m256 h2 = _mm256_set1_ps(H.m[2]), h3 = _mm256_set1_ps(H.m[3]);
  const __m256 h4 = _mm256_set1_ps(H.m[4]), h5 = _mm256_set1_ps(H.m[5]);
  const __m256 h6 = _mm256_set1_ps(H.m[6]), h7 = _mm256_set1_ps(H.m[7]);
  const __m256 h8 = _mm256_set1_ps(H.m[8]);
  const __m256i pitch = _mm256_set1_epi32(src.pitch);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i pair_order = _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
  const __m256 zero = _mm256_setzero_ps();
  const __m256 max_u = _mm256_set1_ps(src.width - 1.0f), max_v = _mm256_set1_ps(src.height - 1.0f);
  const double* row0 = reinterpret_cast<const double*>(src.data);
  const double* row1 = reinterpret_cast<const double*>(src.data + src.pitch);
  __m256 sum_s = _mm256_setzero_ps(), sum_ss = _mm256_setzero_ps(), sum_rs = _mm256_setzero_ps();
  for (int k = 0; k < w.num_samples; k += kWindowLanes) {
    const __m256 x = _mm256_loadu_ps(w.x + k), y = _mm256_loadu_ps(w.y + k);
    const __m256 hw = _mm256_fmadd_ps(h6, x, _mm256_fmadd_ps(h7, y, h8));
    const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), hw);
    const __m256 u = _mm256_mul_ps(_mm256_fmadd_ps(h0, x, _mm256_fmadd_ps(h1, y, h2)), inv);
    const __m256 v = _mm256_mul_ps(_mm256_fmadd_ps(h3, x, _mm256_fmadd_ps(h4, y, h5)), inv);
    // Ordered compares are false for NaN, so a degenerate warp fails too.
    const __m256 inside = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(hw, zero, _CMP_GT_OQ), _mm256_cmp_ps(u, zero, _CMP_GE_OQ)),
        _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(v, zero, _CMP_GE_OQ),
                                    _mm256_cmp_ps(u, max_u, _CMP_LT_OQ)),
                      _mm256_cmp_ps(v, max_v, _CMP_LT_OQ)));
    if (_mm256_movemask_ps(inside) != 0xFF) return false;
    const __m256i c0 = _mm256_cvttps_epi32(u), r0 = _mm256_cvttps_epi32(v);
    const __m256 fx = _mm256_sub_ps(u, _mm256_cvtepi32_ps(c0));
    const __m256 fy = _mm256_sub_ps(v, _mm256_cvtepi32_ps(r0));
    const __m256i index =
        _mm256_permutevar8x32_epi32(_mm256_add_epi32(_mm256_mullo_epi32(r0, pitch), c0), pair_order);
    const __m128i low = _mm256_castsi256_si128(index), high = _mm256_extracti128_si256(index, 1);
    // Scale 4: the indices count floats; each gathered double is a tap pair.
    const __m256 top_low = _mm256_castpd_ps(_mm256_i32gather_pd(row0, low, 4));
    const __m256 top_high = _mm256_castpd_ps(_mm256_i32gather_pd(row0, high, 4));
    const __m256 bottom_low = _mm256_castpd_ps(_mm256_i32gather_pd(row1, low, 4));
    const __m256 bottom_high = _mm256_castpd_ps(_mm256_i32gather_pd(row1, high, 4));
    const __m256 p00 = _mm256_shuffle_ps(top_low, top_high, _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 p01 = _mm256_shuffle_ps(top_low, top_high, _MM_SHUFFLE(3, 1, 3, 1));
    const __m256 p10 = _mm256_shuffle_ps(bottom_low, bottom_high, _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 p11 = _mm256_shuffle_ps(bottom_low, bottom_high, _MM_SHUFFLE(3, 1, 3, 1));
    const __m256 top = _mm256_fmadd_ps(fx, _mm256_sub_ps(p01, p00), p00);
    const __m256 bottom = _mm256_fmadd_ps(fx, _mm256_sub_ps(p11, p10), p10);
    __m256 s = _mm256_fmadd_ps(fy, _mm256_sub_ps(bottom, top), top);
    const __m256i real = _mm256_cmpgt_epi32(_mm256_set1_epi32(w.num_samples - k), lane);
    s = _mm256_and_ps(s, _mm256_castsi256_ps(real));
    sum_s = _mm256_add_ps(sum_s, s);
    sum_ss = _mm256_fmadd_ps(s, s, sum_ss);
    sum_rs = _mm256_fmadd_ps(_mm256_loadu_ps(w.value + k), s, sum_rs);
  }
  *out = SourceSums{HorizontalSum(sum_s), HorizontalSum(sum_ss), HorizontalSum(sum_rs)};
  return true;
}
#endif

MSP_HD bool WindowSums(const RefWindow& w, const ImageView& src, const Mat3& H, SourceSums* out) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  return WindowSumsAvx2(w, src, H, out);
#else
  return WindowSumsScalar(w, src, H, out);
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

}  // namespace core
}  // namespace msp

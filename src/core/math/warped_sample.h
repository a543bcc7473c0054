// One warped bilinear sample, the step every form of the matching cost
// repeats: a reference position mapped by the homography into the source,
// accepted only when its whole 2x2 support lies there (0 <= u < width - 1,
// 0 <= v < height - 1, in front of the camera), so the taps need no bounds
// checks. Scalar, and eight lanes at a time with AVX2 where the build has it.
#pragma once

#include <cstdint>

#include "core/math/hd.h"
#include "core/math/image_view.h"
#include "core/math/vec.h"

#if defined(__AVX2__) && defined(__FMA__) && !defined(__CUDACC__)
#define MSP_WINDOW_SUMS_AVX2 1
#include <immintrin.h>
#endif

namespace msp {
namespace core {

// Samples the source at the warp of (x, y); false (value untouched) when the
// bilinear support leaves the source.
MSP_HD bool SampleWarped(const ImageView& src, const Mat3& H, float x, float y, float* value) {
  const float h2 = H.m[6] * x + H.m[7] * y + H.m[8];
  const float inv = 1.0f / h2;
  const float u = (H.m[0] * x + H.m[1] * y + H.m[2]) * inv;
  const float v = (H.m[3] * x + H.m[4] * y + H.m[5]) * inv;
  if (!(h2 > 0.0f && u >= 0.0f && v >= 0.0f && u < src.width - 1.0f && v < src.height - 1.0f)) {
    return false;
  }
  const int c0 = static_cast<int>(u), r0 = static_cast<int>(v);
  const float fx = u - c0, fy = v - r0;
  const float* p0 = src.data + r0 * src.pitch + c0;
  const float* p1 = p0 + src.pitch;
  const float top = p0[0] + fx * (p0[1] - p0[0]);
  const float bottom = p1[0] + fx * (p1[1] - p1[0]);
  *value = top + fy * (bottom - top);
  return true;
}

#if defined(MSP_WINDOW_SUMS_AVX2)
inline float HorizontalSum(__m256 v) {
  const __m128 lo = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  const __m128 pairs = _mm_add_ps(lo, _mm_movehl_ps(lo, lo));
  return _mm_cvtss_f32(_mm_add_ss(pairs, _mm_shuffle_ps(pairs, pairs, 1)));
}

// Eight lanes' homographies and the source bounds, built once per cost:
// one homography in every lane (BroadcastWarp), or one per lane (WarpPerLane).
struct WarpLanes {
  __m256 h[9];
  __m256 max_u, max_v;
  __m256i pitch;
};

// H in every lane: the samples in the lanes are points of one window.
inline WarpLanes BroadcastWarp(const Mat3& H, const ImageView& src) {
  WarpLanes w;
  for (int i = 0; i < 9; ++i) w.h[i] = _mm256_set1_ps(H.m[i]);
  w.max_u = _mm256_set1_ps(src.width - 1.0f);
  w.max_v = _mm256_set1_ps(src.height - 1.0f);
  w.pitch = _mm256_set1_epi32(src.pitch);
  return w;
}

// The homographies H[l] of the lanes set in `lanes` (not 0), one per lane;
// unused lanes repeat the first used lane's, so that their loads stay in
// bounds with or without tests.
inline WarpLanes WarpPerLane(const Mat3* H, uint32_t lanes, const ImageView& src) {
  alignas(32) float columns[9][8];  // lane l of h[i] is H[l].m[i]
  const int first = __builtin_ctz(lanes);
  for (int l = 0; l < 8; ++l) {
    const Mat3& h = ((lanes >> l) & 1u) ? H[l] : H[first];
    for (int i = 0; i < 9; ++i) columns[i][l] = h.m[i];
  }
  WarpLanes w;
  for (int i = 0; i < 9; ++i) w.h[i] = _mm256_load_ps(columns[i]);
  w.max_u = _mm256_set1_ps(src.width - 1.0f);
  w.max_v = _mm256_set1_ps(src.height - 1.0f);
  w.pitch = _mm256_set1_epi32(src.pitch);
  return w;
}

// Eight warped positions: the bilinear cell (index of its top-left pixel,
// fractions fx, fy) and the mask of lanes whose support lies in the source.
// Lanes outside get index 0 and fractions 0, so their loads stay in bounds.
struct WarpedCells {
  __m256i index;
  __m256 fx, fy;
  __m256 inside;
};

// Eight positions mapped into the source: (u, v) and the divisor hw, whose
// sign says whether the point lies in front of the source camera.
struct WarpedPoints {
  __m256 u, v, hw;
};

inline WarpedPoints WarpPoints(const WarpLanes& w, __m256 x, __m256 y) {
  const __m256 hw = _mm256_fmadd_ps(w.h[6], x, _mm256_fmadd_ps(w.h[7], y, w.h[8]));
  const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), hw);
  const __m256 u =
      _mm256_mul_ps(_mm256_fmadd_ps(w.h[0], x, _mm256_fmadd_ps(w.h[1], y, w.h[2])), inv);
  const __m256 v =
      _mm256_mul_ps(_mm256_fmadd_ps(w.h[3], x, _mm256_fmadd_ps(w.h[4], y, w.h[5])), inv);
  return WarpedPoints{u, v, hw};
}

// Lanes whose bilinear support lies in the source with `margin` pixels to
// spare on every side, in front of the camera. Ordered compares are false for
// NaN, so a degenerate warp fails too.
inline __m256 SupportInside(const WarpLanes& w, const WarpedPoints& p, __m256 margin) {
  return _mm256_and_ps(
      _mm256_and_ps(_mm256_cmp_ps(p.hw, _mm256_setzero_ps(), _CMP_GT_OQ),
                    _mm256_cmp_ps(p.u, margin, _CMP_GE_OQ)),
      _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(p.v, margin, _CMP_GE_OQ),
                                  _mm256_cmp_ps(p.u, _mm256_sub_ps(w.max_u, margin), _CMP_LT_OQ)),
                    _mm256_cmp_ps(p.v, _mm256_sub_ps(w.max_v, margin), _CMP_LT_OQ)));
}

// The cells of positions (u, v) inside the source.
inline WarpedCells CellsAt(const WarpLanes& w, __m256 u, __m256 v) {
  const __m256i c0 = _mm256_cvttps_epi32(u), r0 = _mm256_cvttps_epi32(v);
  WarpedCells c;
  c.fx = _mm256_sub_ps(u, _mm256_cvtepi32_ps(c0));
  c.fy = _mm256_sub_ps(v, _mm256_cvtepi32_ps(r0));
  c.index = _mm256_add_epi32(_mm256_mullo_epi32(r0, w.pitch), c0);
  c.inside = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
  return c;
}

inline WarpedCells WarpCells(const WarpLanes& w, __m256 x, __m256 y) {
  const WarpedPoints p = WarpPoints(w, x, y);
  const __m256 inside = SupportInside(w, p, _mm256_setzero_ps());
  WarpedCells c = CellsAt(w, _mm256_and_ps(p.u, inside), _mm256_and_ps(p.v, inside));
  c.inside = inside;
  return c;
}

// WarpCells of positions already known to have their support in the source
// (WholeBoxLanes): no test, every lane inside.
inline WarpedCells WarpCellsInside(const WarpLanes& w, __m256 x, __m256 y) {
  const WarpedPoints p = WarpPoints(w, x, y);
  return CellsAt(w, p.u, p.v);
}

// How far inside the source bounds the warped corners of a box must stay for
// WholeBoxLanes to vouch for the positions within it: far above the warp's
// rounding (about 1e-3 pixels), so a position inside the box that the exact
// warp puts inside is put inside by the float warp too.
constexpr float kWholeBoxMargin = 1.0f / 16.0f;

// The lanes under whose warp every position of the box [x0, x1] x [y0, y1]
// has its bilinear support in the source, by its four corners. Where the
// divisor is positive at the corners it is positive over the box (it is
// affine), and the homography then maps the box onto the convex
// quadrilateral of the corners' images, which lies in the (convex) bounds
// when they do.
inline uint32_t WholeBoxLanes(const WarpLanes& w, float x0, float x1, float y0, float y1) {
  const __m256 margin = _mm256_set1_ps(kWholeBoxMargin);
  __m256 whole = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
  const float xs[4] = {x0, x1, x0, x1}, ys[4] = {y0, y0, y1, y1};
  for (int k = 0; k < 4; ++k) {
    const WarpedPoints p = WarpPoints(w, _mm256_set1_ps(xs[k]), _mm256_set1_ps(ys[k]));
    whole = _mm256_and_ps(whole, SupportInside(w, p, margin));
  }
  return static_cast<uint32_t>(_mm256_movemask_ps(whole));
}

// True when, under the warp broadcast in every lane, every position of the
// box has its support in the source: WholeBoxLanes with the four corners in
// the lanes of one warp.
inline bool WholeBox(const WarpLanes& w, float x0, float x1, float y0, float y1) {
  const WarpedPoints p = WarpPoints(w, _mm256_setr_ps(x0, x1, x0, x1, x0, x1, x0, x1),
                                    _mm256_setr_ps(y0, y0, y1, y1, y0, y0, y1, y1));
  return _mm256_movemask_ps(SupportInside(w, p, _mm256_set1_ps(kWholeBoxMargin))) == 0xFF;
}

// The lanes that may pass CentreInSource at reference pixel (col, row): all
// but those whose centre lands in front of the camera yet outside the
// source by more than kWholeBoxMargin, beyond any rounding of the warp. A
// dropped lane fails CentreInSource, and no window of samples around the
// centre can lie wholly inside either (the warp keeps a window's centre
// within the convex hull of its samples' images), so by WindowNccCost's
// rules it costs kMaxCost. A lane whose divisor is not positive at the
// centre is dropped too: the divisor, affine, is then not positive at some
// sample of any window around it.
inline uint32_t CentreNearSourceLanes(const WarpLanes& w, int col, int row) {
  const WarpedPoints p = WarpPoints(w, _mm256_set1_ps(static_cast<float>(col)),
                                    _mm256_set1_ps(static_cast<float>(row)));
  return static_cast<uint32_t>(
      _mm256_movemask_ps(SupportInside(w, p, _mm256_set1_ps(-kWholeBoxMargin))));
}

inline __m256 Bilinear(const WarpedCells& c, __m256 p00, __m256 p01, __m256 p10, __m256 p11) {
  const __m256 top = _mm256_fmadd_ps(c.fx, _mm256_sub_ps(p01, p00), p00);
  const __m256 bottom = _mm256_fmadd_ps(c.fx, _mm256_sub_ps(p11, p10), p10);
  return _mm256_fmadd_ps(c.fy, _mm256_sub_ps(bottom, top), top);
}

// The bilinear values of eight cells. The two taps of a cell's row are
// adjacent: one 64-bit load fetches both, and two cells share a 128-bit half.
// Plain loads rather than gather instructions (BENCHMARKS.md). Lanes are
// loaded in the order (0, 1, 4, 5 | 2, 3, 6, 7) so that de-interleaving the
// pairs puts the samples back in lane order.
inline __m256 LoadBilinear(const ImageView& src, const WarpedCells& c) {
  // The indices leave the vector as four 64-bit pairs rather than by a
  // store and eight 32-bit reloads (BENCHMARKS.md).
  const __m128i low_half = _mm256_castsi256_si128(c.index);
  const __m128i high_half = _mm256_extracti128_si256(c.index, 1);
  const uint64_t pair[4] = {static_cast<uint64_t>(_mm_cvtsi128_si64(low_half)),
                            static_cast<uint64_t>(_mm_extract_epi64(low_half, 1)),
                            static_cast<uint64_t>(_mm_cvtsi128_si64(high_half)),
                            static_cast<uint64_t>(_mm_extract_epi64(high_half, 1))};
  uint64_t index[8];  // indices are never negative: zero-extended, no sign extension
  for (int k = 0; k < 4; ++k) {
    index[2 * k] = pair[k] & 0xffffffffu;
    index[2 * k + 1] = pair[k] >> 32;
  }
  const float* row0 = src.data;
  const float* row1 = src.data + src.pitch;
  auto pairs = [&](const float* base, int a, int b, int e, int f) {
    const __m128d low = _mm_loadh_pd(_mm_load_sd(reinterpret_cast<const double*>(base + index[a])),
                                     reinterpret_cast<const double*>(base + index[b]));
    const __m128d high = _mm_loadh_pd(_mm_load_sd(reinterpret_cast<const double*>(base + index[e])),
                                      reinterpret_cast<const double*>(base + index[f]));
    return _mm256_castpd_ps(_mm256_insertf128_pd(_mm256_castpd128_pd256(low), high, 1));
  };
  const __m256 top_low = pairs(row0, 0, 1, 4, 5), top_high = pairs(row0, 2, 3, 6, 7);
  const __m256 bottom_low = pairs(row1, 0, 1, 4, 5), bottom_high = pairs(row1, 2, 3, 6, 7);
  return Bilinear(c, _mm256_shuffle_ps(top_low, top_high, _MM_SHUFFLE(2, 0, 2, 0)),
                  _mm256_shuffle_ps(top_low, top_high, _MM_SHUFFLE(3, 1, 3, 1)),
                  _mm256_shuffle_ps(bottom_low, bottom_high, _MM_SHUFFLE(2, 0, 2, 0)),
                  _mm256_shuffle_ps(bottom_low, bottom_high, _MM_SHUFFLE(3, 1, 3, 1)));
}

// Lanes 0 .. n-1 set (n may exceed 8).
inline __m256 FirstLanes(int n) {
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  return _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(n), lane));
}
#endif

}  // namespace core
}  // namespace msp

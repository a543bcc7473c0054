// Photometric matching cost (eq. 2, docs/method.md section 2.3): 1 - NCC over a (2r+1)^2 window
// sampled every `step` pixels (paper: 11x11, every other pixel), the source window warped by the
// plane-induced homography, optionally with COLMAP's bilateral weights. This header holds the
// parameters, the rules every form shares and the general form; the sweeps call the fast form of a
// prepared window (WindowNccCost, window_cost.h; WindowNccCosts, window_batch.h), which takes the
// general form for the windows it cannot prepare.
#pragma once

#include <cmath>

#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/limits.h"
#include "core/math/vec.h"

namespace msp {
namespace core {

// Below this intensity variance (intensities in [0,1]) a window carries no
// signal and NCC is undefined: about 0.08 grey levels of standard deviation.
constexpr float kMinNccVariance = 1e-7f;
// A warped window needs at least this share of its samples inside the source.
constexpr float kMinValidSampleShare = 0.5f;

struct NccParams {
  int window_radius;  // r: offsets -r, -r+step, ..., r
  int window_step;
  int bilateral;        // 0: uniform weights (APD), 1: COLMAP's bilateral weights
  float sigma_spatial;  // pixels
  float sigma_color;    // intensity units ([0,1] images)
};

// Weighted sums of one window: reference r, source s.
struct NccSums {
  float w, r, s, rr, ss, rs;
  int total, valid;
};

// 1 - NCC from the sums; kMaxCost without enough samples or texture.
MSP_HD float NccFromSums(const NccSums& a) {
  if (a.valid == 0 || static_cast<float>(a.valid) < kMinValidSampleShare * a.total) {
    return kMaxCost;
  }
  const float inv_w = 1.0f / a.w;
  const float mr = a.r * inv_w, ms = a.s * inv_w;
  const float var_r = a.rr * inv_w - mr * mr;
  const float var_s = a.ss * inv_w - ms * ms;
  if (var_r < kMinNccVariance || var_s < kMinNccVariance) return kMaxCost;
  const float ncc = (a.rs * inv_w - mr * ms) / sqrtf(var_r * var_s);
  return fminf(fmaxf(1.0f - ncc, 0.0f), kMaxCost);
}

// True when reference pixel (col, row) maps into the source under H. A view
// the pixel does not map into does not see it: every matching cost is then
// kMaxCost, whatever the rest of its window matches.
MSP_HD bool CentreInSource(const Mat3& H, const ImageView& src, int col, int row) {
  float u = 0.0f, v = 0.0f;
  return ApplyHomography(H, static_cast<float>(col), static_cast<float>(row), &u, &v) &&
         u >= 0.0f && v >= 0.0f && u <= src.width - 1.0f && v <= src.height - 1.0f;
}

// 1 - NCC in [0, 2] for the window centred at reference pixel (col, row): the
// general form, for any window size, with bilateral weights and windows over
// the image borders. The warp of a grid is incremental: one homogeneous add
// and one divide per sample.
MSP_HD float GeneralNccCost(const ImageView& ref, const ImageView& src, const Mat3& H, int col,
                            int row, const NccParams& p) {
  if (!CentreInSource(H, src, col, row)) return kMaxCost;
  const int r = p.window_radius;
  const int step = p.window_step;
  const float x0 = static_cast<float>(col - r);
  const float y0 = static_cast<float>(row - r);
  float row_h[3] = {H.m[0] * x0 + H.m[1] * y0 + H.m[2], H.m[3] * x0 + H.m[4] * y0 + H.m[5],
                    H.m[6] * x0 + H.m[7] * y0 + H.m[8]};
  const float dx[3] = {H.m[0] * step, H.m[3] * step, H.m[6] * step};
  const float dy[3] = {H.m[1] * step, H.m[4] * step, H.m[7] * step};
  NccSums a = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0, 0};
  const float center = ref.At(col, row);
  const float inv_2ss = p.bilateral ? 1.0f / (2.0f * p.sigma_spatial * p.sigma_spatial) : 0.0f;
  const float inv_2cc = p.bilateral ? 1.0f / (2.0f * p.sigma_color * p.sigma_color) : 0.0f;
  for (int oy = -r; oy <= r; oy += step) {
    const int rr = row + oy;
    float h0 = row_h[0], h1 = row_h[1], h2 = row_h[2];
    for (int ox = -r; ox <= r; ox += step, h0 += dx[0], h1 += dx[1], h2 += dx[2]) {
      const int cc = col + ox;
      if (rr < 0 || cc < 0 || rr >= ref.height || cc >= ref.width) continue;
      ++a.total;
      if (h2 <= 0.0f) continue;
      const float inv = 1.0f / h2;
      float s;
      if (!SampleBilinear(src, h0 * inv, h1 * inv, &s)) continue;
      ++a.valid;
      const float rv = ref.At(cc, rr);
      float w = 1.0f;
      if (p.bilateral) {
        const float dc = rv - center;
        w = expf(-static_cast<float>(ox * ox + oy * oy) * inv_2ss - dc * dc * inv_2cc);
      }
      a.w += w;
      a.r += w * rv;
      a.s += w * s;
      a.rr += w * rv * rv;
      a.ss += w * s * s;
      a.rs += w * rv * s;
    }
    row_h[0] += dy[0];
    row_h[1] += dy[1];
    row_h[2] += dy[2];
  }
  return NccFromSums(a);
}

}  // namespace core
}  // namespace msp

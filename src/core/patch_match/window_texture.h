// How much texture a pixel's matching window has: below kTexturedWindowStd
// its photometric cost is noise and cannot choose a plane (segment planes
// and surface normals then decide instead).
#pragma once

#include <cmath>

#include "core/math/hd.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Intensities in [0, 1]: about 5 grey levels. A flat wall under camera noise
// stays below it.
constexpr float kTexturedWindowStd = 0.02f;

// Standard deviation (intensities in [0, 1]) of the reference samples of the
// matching window at (col, row); 0 for a window with no sample.
MSP_HD float WindowTextureStd(const PassParams& p, int col, int row) {
  const int r = p.ncc.window_radius, step = p.ncc.window_step;
  float sum = 0.0f, sum_sq = 0.0f;
  int n = 0;
  for (int oy = -r; oy <= r; oy += step) {
    for (int ox = -r; ox <= r; ox += step) {
      const int c = col + ox, y = row + oy;
      if (!p.ref_image.Contains(c, y)) continue;
      const float v = p.ref_image.At(c, y);
      sum += v;
      sum_sq += v * v;
      ++n;
    }
  }
  if (n == 0) return 0.0f;
  const float mean = sum / n;
  const float var = sum_sq / n - mean * mean;
  return var > 0.0f ? sqrtf(var) : 0.0f;
}

// Largest central difference of the reference image at (col, row), in
// intensity per pixel: high on edges and texture, noise-level on a flat wall.
MSP_HD float EdgeStrength(const ImageView& image, int col, int row) {
  const int l = col > 0 ? col - 1 : col, r = col + 1 < image.width ? col + 1 : col;
  const int u = row > 0 ? row - 1 : row, d = row + 1 < image.height ? row + 1 : row;
  const float gx = fabsf(image.At(r, row) - image.At(l, row));
  const float gy = fabsf(image.At(col, d) - image.At(col, u));
  return gx > gy ? gx : gy;
}

MSP_HD bool IsWeaklyTextured(const PassParams& p, int col, int row) {
  return WindowTextureStd(p, col, row) < kTexturedWindowStd;
}

}  // namespace core
}  // namespace msp

// Texture that can fix a depth: the standard deviation of a window's
// intensities about the best-fitting intensity ramp (a + b x + c y), not
// about their mean. A window on a soft gradient (a cloud's edge, a sky
// darkening overhead, shading across a wall) has a raw standard deviation
// above core::kTexturedWindowStd, but its content is a ramp, and a ramp
// shifted along itself is the same ramp up to an offset: NCC matches it at
// every depth. An edge, a corner or a textured surface leaves a residual.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/parallel_for.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {

// Per pixel of `image`, the residual standard deviation of the intensities in
// the (2 radius + 1)^2 box around it (clipped at the image's borders) about
// their least-squares ramp. Summed-area tables of I, I^2, I x and I y: the
// same cost at any radius. The rows share out over up to `num_threads` threads.
inline std::vector<float> RampFreeTexture(const core::ImageView& image, int radius,
                                          int num_threads = 1) {
  const int w = image.width, h = image.height;
  const size_t stride = static_cast<size_t>(w) + 1;
  std::vector<double> s(stride * (h + 1), 0.0), s2(s), sx(s), sy(s);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const double v = image.At(col, row);
      const size_t k = (row + 1) * stride + col + 1, up = row * stride + col + 1,
                   left = (row + 1) * stride + col, diag = row * stride + col;
      s[k] = v + s[up] + s[left] - s[diag];
      s2[k] = v * v + s2[up] + s2[left] - s2[diag];
      sx[k] = v * col + sx[up] + sx[left] - sx[diag];
      sy[k] = v * row + sy[up] + sy[left] - sy[diag];
    }
  }
  std::vector<float> out(static_cast<size_t>(w) * h, 0.0f);
  ParallelFor(0, h, num_threads, [&](int row) {
    const int r0 = std::max(0, row - radius), r1 = std::min(h, row + radius + 1);
    for (int col = 0; col < w; ++col) {
      const int c0 = std::max(0, col - radius), c1 = std::min(w, col + radius + 1);
      const auto box = [&](const std::vector<double>& t) {
        return t[r1 * stride + c1] - t[r0 * stride + c1] - t[r1 * stride + c0] +
               t[r0 * stride + c0];
      };
      const double nx = c1 - c0, ny = r1 - r0, n = nx * ny;
      // Centred coordinates over a rectangle: sum(u v) = 0, and sum(u^2) is
      // ny times the variance of the columns c0..c1-1 times nx.
      const double mean_x = 0.5 * (c0 + c1 - 1), mean_y = 0.5 * (r0 + r1 - 1);
      const double uu = ny * nx * (nx * nx - 1.0) / 12.0, vv = nx * ny * (ny * ny - 1.0) / 12.0;
      const double sum = box(s), mean = sum / n;
      const double iu = box(sx) - mean_x * sum, iv = box(sy) - mean_y * sum;
      double var = box(s2) / n - mean * mean;
      if (uu > 0.0) var -= iu * iu / uu / n;
      if (vv > 0.0) var -= iv * iv / vv / n;
      out[static_cast<size_t>(row) * w + col] =
          var > 0.0 ? static_cast<float>(std::sqrt(var)) : 0.0f;
    }
  });
  return out;
}

}  // namespace msp

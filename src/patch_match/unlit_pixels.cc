#include "patch_match/unlit_pixels.h"

#include <algorithm>

#include "base/parallel_for.h"

namespace msp {

std::vector<uint8_t> UnlitPixels(const DenseMap& gray, int radius, float black_level,
                                 int num_threads) {
  if (!(black_level > 0.0f)) return {};
  const int width = gray.width, height = gray.height;
  // A window is unlit when its brightest pixel is: the maximum over the rows
  // of each column first, then over the columns of those.
  std::vector<float> column_max(static_cast<size_t>(width) * height);
  ParallelFor(0, height, num_threads, [&](int row) {
    const int r0 = std::max(0, row - radius), r1 = std::min(height - 1, row + radius);
    for (int col = 0; col < width; ++col) {
      float m = gray.At(r0, col);
      for (int r = r0 + 1; r <= r1; ++r) m = std::max(m, gray.At(r, col));
      column_max[static_cast<size_t>(row) * width + col] = m;
    }
  });
  std::vector<uint8_t> unlit(column_max.size(), 0);
  std::vector<int> count(height, 0);
  ParallelFor(0, height, num_threads, [&](int row) {
    const float* line = column_max.data() + static_cast<size_t>(row) * width;
    for (int col = 0; col < width; ++col) {
      const int c0 = std::max(0, col - radius), c1 = std::min(width - 1, col + radius);
      const float m = *std::max_element(line + c0, line + c1 + 1);
      if (m < black_level) {
        unlit[static_cast<size_t>(row) * width + col] = 1;
        ++count[row];
      }
    }
  });
  for (int c : count) {
    if (c > 0) return unlit;
  }
  return {};
}

}  // namespace msp

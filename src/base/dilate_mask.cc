#include "base/dilate_mask.h"

#include <algorithm>

namespace msp {

std::vector<uint8_t> DilateMask(const std::vector<uint8_t>& mask, int width, int height,
                                int radius) {
  // Separable: along the rows, then along the columns of that.
  std::vector<uint8_t> horizontal(mask.size(), 0);
  for (int row = 0; row < height; ++row) {
    const uint8_t* src = mask.data() + static_cast<size_t>(row) * width;
    uint8_t* dst = horizontal.data() + static_cast<size_t>(row) * width;
    for (int col = 0; col < width; ++col) {
      if (!src[col]) continue;
      for (int c = std::max(0, col - radius); c <= std::min(width - 1, col + radius); ++c) {
        dst[c] = 1;
      }
    }
  }
  std::vector<uint8_t> out(mask.size(), 0);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      if (!horizontal[static_cast<size_t>(row) * width + col]) continue;
      for (int r = std::max(0, row - radius); r <= std::min(height - 1, row + radius); ++r) {
        out[static_cast<size_t>(r) * width + col] = 1;
      }
    }
  }
  return out;
}

}  // namespace msp

// Trivially copyable views of float images (host or device memory) and the
// software bilinear sampler used by both back-ends.
#pragma once

#include <cmath>

#include "core/math/hd.h"

namespace msp {
namespace core {

struct ImageView {
  const float* data;  // row-major, `pitch` floats per row
  int width;
  int height;
  int pitch;
  MSP_HD float At(int col, int row) const { return data[row * pitch + col]; }
  MSP_HD bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height;
  }
};

struct MutableImageView {
  float* data;
  int width;
  int height;
  int pitch;
  MSP_HD float& At(int col, int row) const { return data[row * pitch + col]; }
  MSP_HD ImageView Const() const { return ImageView{data, width, height, pitch}; }
};

// Bilinear interpolation at (x, y) where pixel (c, r) sits at x = c, y = r.
// Returns false (and leaves *value untouched) when the 2x2 support leaves the
// image: out-of-bounds is explicit, never clamped into fake data.
MSP_HD bool SampleBilinear(const ImageView& image, float x, float y, float* value) {
  if (!(x >= 0.0f && y >= 0.0f && x <= image.width - 1.0f && y <= image.height - 1.0f)) {
    return false;
  }
  int c0 = static_cast<int>(x);
  int r0 = static_cast<int>(y);
  // On the last column/row the right/bottom neighbour has weight 0: step back
  // one pixel so the 2x2 support stays inside the image.
  if (c0 >= image.width - 1) c0 = image.width - 2;
  if (r0 >= image.height - 1) r0 = image.height - 2;
  if (c0 < 0 || r0 < 0) {  // 1-pixel-wide image
    *value = image.At(0, 0);
    return true;
  }
  const float fx = x - c0;
  const float fy = y - r0;
  const float* row0 = image.data + r0 * image.pitch + c0;
  const float* row1 = row0 + image.pitch;
  const float top = row0[0] + fx * (row0[1] - row0[0]);
  const float bottom = row1[0] + fx * (row1[1] - row1[0]);
  *value = top + fy * (bottom - top);
  return true;
}

}  // namespace core
}  // namespace msp

// A float array in COLMAP's Mat<float> layout: channel-planar, row-major,
// index(row, col, c) = c * width * height + row * width + col. Used for depth
// maps (1 channel), normal maps (3), grey images (1) and colour images (3).
#pragma once

#include <cstddef>
#include <vector>

namespace msp {

struct DenseMap {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> data;

  DenseMap() = default;
  DenseMap(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), data(static_cast<size_t>(w) * h * c, fill) {}

  bool Empty() const { return data.empty(); }
  size_t Index(int row, int col, int c = 0) const {
    return (static_cast<size_t>(c) * height + row) * width + col;
  }
  float& At(int row, int col, int c = 0) { return data[Index(row, col, c)]; }
  float At(int row, int col, int c = 0) const { return data[Index(row, col, c)]; }
  // Pointer to the start of channel c (a width x height plane).
  float* Plane(int c) { return data.data() + static_cast<size_t>(c) * width * height; }
  const float* Plane(int c) const { return data.data() + static_cast<size_t>(c) * width * height; }
};

}  // namespace msp

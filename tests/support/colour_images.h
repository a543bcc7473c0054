// Colour images with known regions for the segmentation and CRF tests.
#pragma once

#include <array>
#include <cstdint>

#include "base/dense_map.h"
#include "core/math/rng.h"

namespace msp {
namespace test {

using Rgb = std::array<float, 3>;

// Sensor-like noise: uniform in [-amplitude / 2, amplitude / 2), a pure hash
// of (seed, pixel index, channel).
inline float PixelNoise(uint32_t seed, int pixel, int channel, float amplitude) {
  return amplitude * (core::RandomUniform(core::RngKey(seed, 0, 0, 0, pixel), channel) - 0.5f);
}

// Colour `left` on the columns before `edge_col`, `right` from it on (an
// edge_col of 0 or the width gives one colour), plus PixelNoise of `noise`
// amplitude from `seed`.
inline DenseMap TwoColourImage(int width, int height, int edge_col, const Rgb& left,
                               const Rgb& right, float noise, uint32_t seed) {
  DenseMap image(width, height, 3);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const Rgb& rgb = col < edge_col ? left : right;
      for (int c = 0; c < 3; ++c) {
        image.At(row, col, c) = rgb[c] + PixelNoise(seed, row * width + col, c, noise);
      }
    }
  }
  return image;
}

}  // namespace test
}  // namespace msp

// Small float images for the per-pixel core's tests: an owned image with its
// ImageView, noise and flat images, smooth value-noise texture, a mild
// projective warp, and depth-edge maps.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/value_noise.h"
#include "core/math/image_view.h"
#include "core/math/rng.h"
#include "core/math/vec.h"
#include "core/prior/segment_crossing.h"

namespace msp {
namespace test {

// A row-major float image that owns its pixels.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> data;

  float& At(int col, int row) { return data[row * width + col]; }
  core::ImageView View() const { return core::ImageView{data.data(), width, height, width}; }
};

// Every pixel `value`: no texture, so no matching signal.
inline Image FlatImage(int width, int height, float value) {
  return Image{width, height, std::vector<float>(static_cast<size_t>(width) * height, value)};
}

// Independent uniform pixels in [offset, offset + gain) (gain may be
// negative), the same for every gain and offset of one seed: images of one
// seed differ by an affine map of their values only.
inline Image NoiseImage(int width, int height, uint64_t seed, float gain = 1.0f,
                        float offset = 0.0f) {
  Image image = FlatImage(width, height, 0.0f);
  for (int i = 0; i < width * height; ++i) {
    image.data[i] = offset + gain * core::RandomUniform(core::Mix64(seed), i);
  }
  return image;
}

// A mild projective warp: scaled, sheared and tilted a little, then shifted.
inline core::Mat3 MildWarp(float shift_x, float shift_y) {
  return core::Mat3{{1.03f, 0.02f, shift_x, -0.015f, 0.98f, shift_y, 2e-4f, -1e-4f, 1.0f}};
}

// A depth-edge map (1 = edge) that owns its pixels.
struct EdgeMap {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> bits;

  core::BoundaryView View() const { return core::BoundaryView{bits.data(), width, height, width}; }
};

// No edge at all.
inline EdgeMap NoEdges(int width, int height) {
  return EdgeMap{width, height, std::vector<uint8_t>(static_cast<size_t>(width) * height, 0)};
}

// A vertical edge two pixels thick, as boundary maps mark both sides of a
// label change, at columns `col` and `col + 1`.
inline EdgeMap VerticalEdge(int width, int height, int col) {
  EdgeMap edges = NoEdges(width, height);
  for (int row = 0; row < height; ++row) {
    edges.bits[row * width + col] = edges.bits[row * width + col + 1] = 1;
  }
  return edges;
}

}  // namespace test
}  // namespace msp

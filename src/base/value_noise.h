// Smooth value noise, the texture of synthetic images (the device self-check's
// problem, the tests' planes): a uniform value in [0, 1) at every integer
// lattice point (i, j), a hash of (i, j) and the seed, bilinear in between.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/math/rng.h"

namespace msp {

inline float ValueNoise(float x, float y, uint64_t seed) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  auto lattice = [seed](int a, int b) {
    const uint64_t cell =
        (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) ^ static_cast<uint32_t>(b);
    return static_cast<float>(core::Mix64(cell ^ seed) >> 40) / 16777216.0f;  // 24 bits
  };
  const float u = x - fx, v = y - fy;
  const float top = lattice(i, j) + u * (lattice(i + 1, j) - lattice(i, j));
  const float bottom = lattice(i, j + 1) + u * (lattice(i + 1, j + 1) - lattice(i, j + 1));
  return top + v * (bottom - top);
}

}  // namespace msp

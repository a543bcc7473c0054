// Counter-based random numbers: a value is a pure hash of its key
// (seed, image, pass, iteration, pixel, draw), so a run is reproducible for any
// thread count or back-end, and CPU and CUDA draw identical numbers.
#pragma once

#include <cstdint>

#include "core/math/hd.h"

namespace msp {
namespace core {

// SplitMix64 finaliser: a bijective 64-bit mixer with good avalanche.
MSP_HD uint64_t Mix64(uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Key of one pixel's random stream in one iteration of one pass.
MSP_HD uint64_t RngKey(uint32_t seed, uint32_t image, uint32_t pass, uint32_t iteration,
                       uint32_t pixel) {
  uint64_t k = Mix64((static_cast<uint64_t>(seed) << 32) | image);
  k = Mix64(k ^ ((static_cast<uint64_t>(pass) << 32) | iteration));
  return Mix64(k ^ pixel);
}

// Uniform float in [0, 1) for draw number `draw` of a stream.
MSP_HD float RandomUniform(uint64_t key, uint32_t draw) {
  const uint64_t bits = Mix64(key ^ (0xD1B54A32D192ED03ull * (draw + 1ull)));
  return static_cast<float>(bits >> 40) * (1.0f / 16777216.0f);  // 24 random bits
}

// A stream: the key plus a running draw counter.
struct Rng {
  uint64_t key;
  uint32_t draw;
  MSP_HD float Uniform() { return RandomUniform(key, draw++); }
  MSP_HD float Uniform(float lo, float hi) { return lo + (hi - lo) * Uniform(); }
};

MSP_HD Rng MakeRng(uint64_t key) { return Rng{key, 0u}; }

}  // namespace core
}  // namespace msp

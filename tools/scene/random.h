// Counter-based random numbers for the scene generator: every draw is a pure
// function of (seed, stream, index), so the output does not depend on thread
// scheduling or on the standard library's distribution implementations.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/math/rng.h"

namespace msp {
namespace scene {

// The same SplitMix64 mixer as the stereo core's counter-based generator.
using core::Mix64;

inline uint64_t HashKey(uint64_t seed, uint64_t stream, uint64_t index) {
  return Mix64(Mix64(Mix64(seed) ^ stream) ^ index);
}

// Uniform in [0, 1) with 53 random bits.
inline double Uniform01(uint64_t seed, uint64_t stream, uint64_t index) {
  return static_cast<double>(HashKey(seed, stream, index) >> 11) * (1.0 / 9007199254740992.0);
}

// Standard normal by Box-Muller from two counter draws.
inline double StandardNormal(uint64_t seed, uint64_t stream, uint64_t index) {
  constexpr double kTwoPi = 6.283185307179586;
  // 1 - u keeps the log argument in (0, 1].
  const double u1 = 1.0 - Uniform01(seed, stream, 2 * index);
  const double u2 = Uniform01(seed, stream, 2 * index + 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

// Stream ids keep the draws of different generator stages independent.
enum Stream : uint64_t {
  kStreamCameraJitter = 1,
  kStreamImageNoise = 2,
  kStreamTrackSampling = 3,
};

}  // namespace scene
}  // namespace msp

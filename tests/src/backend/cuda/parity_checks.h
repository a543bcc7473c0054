// The tolerances of the per-kernel parity tests and the share of pixels
// whose plane flipped between the back-ends (sweep_parity_test.cc states why
// planes may flip at all).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace msp {
namespace test {

constexpr float kParityDepthTolerance = 1e-3f;  // relative
constexpr double kMaxFlippedShare = 0.01;

// Share of pixels whose depth or view mask differ beyond the tolerance;
// `State` has vectors `depth` and `mask`.
template <typename State>
double FlippedShare(const State& a, const State& b) {
  int flipped = 0;
  for (size_t i = 0; i < a.depth.size(); ++i) {
    const bool same_depth =
        std::fabs(a.depth[i] - b.depth[i]) <= kParityDepthTolerance * a.depth[i];
    if (!same_depth || a.mask[i] != b.mask[i]) ++flipped;
  }
  return static_cast<double>(flipped) / a.depth.size();
}

// Share of the entries of two equally long class maps that differ.
inline double DifferingShare(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int differ = 0;
  for (size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
  return static_cast<double>(differ) / a.size();
}

}  // namespace test
}  // namespace msp

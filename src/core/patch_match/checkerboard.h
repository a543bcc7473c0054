// ACMH adaptive checkerboard sampling. In a red-black sweep a pixel of one
// colour looks at 8 regions of opposite-colour pixels: 4 near "V" shapes and
// 4 far strips, one of each pointing up, down, left and right. The lowest-cost
// pixel of each region proposes its plane.
#pragma once

#include "core/math/hd.h"

namespace msp {
namespace core {

constexpr int kNumRegions = 8;
// A near V: (0,1), (+-1,2), (+-2,3), (+-3,4) rotated to each direction.
constexpr int kNearSamples = 7;
// A far strip: distances 3, 5, ..., 23 along the direction (odd = other colour).
constexpr int kFarSamples = 11;
constexpr int kFarStart = 3;
constexpr int kFarStep = 2;

// Offset (dx, dy) of sample i of region `region` (0-3 near, 4-7 far; within
// each, directions up, down, left, right). Returns the number of samples.
MSP_HD int RegionSize(int region) { return region < 4 ? kNearSamples : kFarSamples; }

MSP_HD void RegionOffset(int region, int i, int* dx, int* dy) {
  int along, across;
  if (region < 4) {
    // i = 0 -> tip (0, 1); then pairs (-k, k+1), (k, k+1) for k = 1..3.
    const int k = (i + 1) / 2;
    along = k + 1;
    across = (i == 0) ? 0 : ((i & 1) ? -k : k);
  } else {
    along = kFarStart + kFarStep * i;
    across = 0;
  }
  switch (region & 3) {
    case 0:  // up
      *dx = across;
      *dy = -along;
      break;
    case 1:  // down
      *dx = across;
      *dy = along;
      break;
    case 2:  // left
      *dx = -along;
      *dy = across;
      break;
    default:  // right
      *dx = along;
      *dy = across;
      break;
  }
}

}  // namespace core
}  // namespace msp

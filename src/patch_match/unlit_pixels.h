// Pixels with nothing to match: those whose whole matching window is darker
// than a black level. No light came back from there (a black backdrop, the
// night sky), so the window holds only the sensor's noise and quantisation:
// NCC of noise agrees with any plane, and planes propagated into such a
// region from its edges fuse into points floating around the object. These
// pixels keep no plane and are never scored (core::IsUnlit). A textureless
// but lit surface (a wall) is not affected: its windows are bright.
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"

namespace msp {

// 1 where every pixel of the (2 radius + 1)^2 window around the pixel is
// below `black_level` (grey, 0..1), else 0; empty when no pixel is unlit or
// black_level is 0 (the check is off).
std::vector<uint8_t> UnlitPixels(const DenseMap& gray, int radius, float black_level);

}  // namespace msp

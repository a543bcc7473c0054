// Pixels of the finest round that keep the plane the coarser rounds carried
// up: those whose matching window is weakly textured (core::IsWeaklyTextured)
// and lies on that plane, whose neighbours a window's radius away hold the
// same plane. At full size such a window's photometric cost is flat noise, so
// the red-black sweeps and the local refinement could only move the depth at
// random, while these pixels are a third or more of an image; their planes
// were chosen where an 11x11 window still saw the surface's creases and edges.
// Near a depth edge (two surfaces of alike colour) the carried-up planes are
// blocky, and the sweeps put the edge in place: those pixels are swept. Held
// pixels stay scored and filtered, and propagate their planes to the pixels
// around them (core::IsHeld).
#pragma once

#include <cstdint>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"

namespace msp {

// 1 at each weakly textured pixel of params' reference image whose plane the
// pixels around it continue (params.state), else 0; empty when none is.
std::vector<uint8_t> HeldPixels(const core::PassParams& params, int num_threads);

}  // namespace msp

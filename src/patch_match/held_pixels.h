// Pixels of the finest round that keep the plane the coarser rounds carried
// up: those whose matching window is weakly textured (core::IsWeaklyTextured).
// At full size their photometric cost is flat noise, so the red-black sweeps
// and the local refinement there can only move their depth at random, while
// they are a third or more of the pixels; their planes were chosen where an
// 11x11 window still saw the surface's creases and edges. They stay scored
// and filtered, and propagate their planes to the textured pixels around them
// (core::IsHeld).
#pragma once

#include <cstdint>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"

namespace msp {

// 1 at each weakly textured pixel of params' reference image, else 0; empty
// when none is.
std::vector<uint8_t> WeaklyTexturedPixels(const core::PassParams& params, int num_threads);

}  // namespace msp

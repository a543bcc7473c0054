// Plain C++ launcher of the device checkerboard kernel (no CUDA types here).
#pragma once

#include "core/patch_match_kernel.h"

namespace msp {
namespace cuda {

// Runs UpdatePixel for every pixel of `color` (0 red, 1 black) on the device.
// `device_params` and every pointer inside it must be device memory.
void LaunchCheckerboard(const core::PassParams* device_params, int width, int height, int color,
                        int iteration);

}  // namespace cuda
}  // namespace msp

// Plain C++ launchers of the per-pixel sweep kernels (no CUDA types here).
// Each kernel is one thread per pixel calling the src/core function the CPU
// driver calls for that pixel (src/patch_match/sweeps.cc,
// src/deformable/deformable_sweeps.cc). `device_params` and every pointer
// inside it must be device memory of the current device. Every launcher
// checks the launch and waits for the kernel (MSP_CUDA_CHECK_LAUNCH).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/deformable/reliability.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace cuda {

// InitializePixel for every pixel (random planes; the costs are ScorePixel's).
void LaunchInitialize(const core::PassParams* device_params, int width, int height);

// ScorePixel for every pixel.
void LaunchScore(const core::PassParams* device_params, int width, int height);

// UpdatePixel for every pixel of `color` (0 red, 1 black): half of one
// red-black iteration.
void LaunchCheckerboard(const core::PassParams* device_params, int width, int height, int color,
                        int iteration);

// LocalRefinePixel for every pixel.
void LaunchLocalRefine(const core::PassParams* device_params, int width, int height);

// LocalRefineAndClassifyPixel for every pixel, its class into device_classes.
void LaunchLocalRefineAndClassify(const core::PassParams* device_params,
                                  const core::ReliabilityParams& rp, uint8_t* device_classes,
                                  int width, int height);

// The largest local memory (stack) per thread of these kernels on the
// current device: what the device reserves for every resident thread.
size_t MaxKernelLocalBytes();

}  // namespace cuda
}  // namespace msp

// The launch geometry of every per-pixel kernel: one thread per pixel in
// 16 x 16 blocks covering the image; and the local memory a kernel takes.
#pragma once

#include <cstddef>

#include "backend/cuda/cuda_check.h"

namespace msp {
namespace cuda {

constexpr int kBlockSide = 16;

inline dim3 PixelBlock() { return dim3(kBlockSide, kBlockSide); }

inline dim3 PixelGrid(int width, int height) {
  return dim3((width + kBlockSide - 1) / kBlockSide, (height + kBlockSide - 1) / kBlockSide);
}

// The local memory (stack) per thread of `kernel` on the current device.
template <typename Kernel>
size_t KernelLocalBytes(Kernel kernel) {
  cudaFuncAttributes attributes;
  MSP_CUDA_CHECK(cudaFuncGetAttributes(&attributes, kernel));
  return attributes.localSizeBytes;
}

}  // namespace cuda
}  // namespace msp

// The launch geometry of every per-pixel kernel: one thread per pixel in
// 16 x 16 blocks covering the image.
#pragma once

namespace msp {
namespace cuda {

constexpr int kBlockSide = 16;

inline dim3 PixelBlock() { return dim3(kBlockSide, kBlockSide); }

inline dim3 PixelGrid(int width, int height) {
  return dim3((width + kBlockSide - 1) / kBlockSide, (height + kBlockSide - 1) / kBlockSide);
}

}  // namespace cuda
}  // namespace msp

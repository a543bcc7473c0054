#include "backend/cuda/sweep_kernels.h"

#include <algorithm>

#include "backend/cuda/cuda_check.h"
#include "backend/cuda/launch_geometry.cuh"
#include "core/deformable/refine_and_classify.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace cuda {
namespace {

// The pixel of this thread; false outside the image.
__device__ bool ThreadPixel(const core::PassParams* params, int* col, int* row) {
  *col = blockIdx.x * blockDim.x + threadIdx.x;
  *row = blockIdx.y * blockDim.y + threadIdx.y;
  return *col < params->state.width && *row < params->state.height;
}

__global__ void InitializeKernel(const core::PassParams* params) {
  int col, row;
  if (ThreadPixel(params, &col, &row)) core::InitializePixel(*params, col, row);
}

__global__ void ScoreKernel(const core::PassParams* params) {
  int col, row;
  if (ThreadPixel(params, &col, &row)) core::ScorePixel(*params, col, row);
}

// Pixels of one colour read only pixels of the other, so one colour's
// threads never race.
__global__ void CheckerboardKernel(const core::PassParams* params, int color, int iteration) {
  int col, row;
  if (!ThreadPixel(params, &col, &row) || ((col + row) & 1) != color) return;
  core::UpdatePixel(*params, col, row, iteration);
}

__global__ void LocalRefineKernel(const core::PassParams* params) {
  int col, row;
  if (ThreadPixel(params, &col, &row)) core::LocalRefinePixel(*params, col, row);
}

__global__ void LocalRefineAndClassifyKernel(const core::PassParams* params,
                                             core::ReliabilityParams rp, uint8_t* classes) {
  int col, row;
  if (!ThreadPixel(params, &col, &row)) return;
  classes[row * params->state.width + col] =
      core::LocalRefineAndClassifyPixel(*params, col, row, rp);
}

}  // namespace

void LaunchInitialize(const core::PassParams* device_params, int width, int height) {
  InitializeKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params);
  MSP_CUDA_CHECK_LAUNCH();
}

void LaunchScore(const core::PassParams* device_params, int width, int height) {
  ScoreKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params);
  MSP_CUDA_CHECK_LAUNCH();
}

void LaunchCheckerboard(const core::PassParams* device_params, int width, int height, int color,
                        int iteration) {
  CheckerboardKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params, color, iteration);
  MSP_CUDA_CHECK_LAUNCH();
}

void LaunchLocalRefine(const core::PassParams* device_params, int width, int height) {
  LocalRefineKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params);
  MSP_CUDA_CHECK_LAUNCH();
}

void LaunchLocalRefineAndClassify(const core::PassParams* device_params,
                                  const core::ReliabilityParams& rp, uint8_t* device_classes,
                                  int width, int height) {
  LocalRefineAndClassifyKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params, rp,
                                                                           device_classes);
  MSP_CUDA_CHECK_LAUNCH();
}

size_t MaxKernelLocalBytes() {
  return std::max({KernelLocalBytes(InitializeKernel), KernelLocalBytes(ScoreKernel),
                   KernelLocalBytes(CheckerboardKernel), KernelLocalBytes(LocalRefineKernel),
                   KernelLocalBytes(LocalRefineAndClassifyKernel)});
}

}  // namespace cuda
}  // namespace msp

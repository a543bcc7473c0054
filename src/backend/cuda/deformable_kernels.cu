#include <algorithm>

#include "backend/cuda/cuda_check.h"
#include "backend/cuda/deformable_kernels.h"
#include "backend/cuda/launch_geometry.cuh"
#include "core/deformable/deformable_sweep_pixel.h"
#include "core/deformable/reliability.h"

namespace msp {
namespace cuda {
namespace {

// The pixel of this thread in the band; false outside it.
__device__ bool BandPixel(const DeformableBand& band, int width, int* col, int* row) {
  *col = blockIdx.x * blockDim.x + threadIdx.x;
  *row = band.row_begin + blockIdx.y * blockDim.y + threadIdx.y;
  return *col < width && *row < band.row_end;
}

__global__ void ClassifyKernel(const core::PassParams* params, core::ReliabilityParams rp,
                               uint8_t* classes) {
  const int col = blockIdx.x * blockDim.x + threadIdx.x;
  const int row = blockIdx.y * blockDim.y + threadIdx.y;
  if (col >= params->state.width || row >= params->state.height) return;
  classes[row * params->state.width + col] = core::ClassifyPixel(*params, col, row, rp);
}

__global__ void FindAnchorsKernel(const core::PassParams* params, DeformableBand band, int width,
                                  int iteration, unsigned long long* anchored) {
  int col, row;
  if (!BandPixel(band, width, &col, &row)) return;
  const int k = band.slot[row * width + col];
  if (k < 0) return;
  const int b = k - band.slot_begin;
  if (core::FindPixelAnchors(*params, band.maps, band.anchor_params, col, row, iteration,
                             &band.hits[b], &band.anchors[b],
                             band.solutions != nullptr ? &band.solutions[b] : nullptr)) {
    atomicAdd(anchored, 1ull);  // a sum: the same whatever order the threads add in
  }
}

// Pixels of one colour read only the other colour's planes, their own
// anchors and the snapshot, so one colour's threads never race.
template <bool kSharesPairs>
__global__ void DeformableSweepKernel(const core::PassParams* params, DeformableBand band,
                                      int width, int color, int iteration) {
  int col, row;
  if (!BandPixel(band, width, &col, &row) || ((col + row) & 1) != color) return;
  const int k = band.slot[row * width + col];
  const int b = k - band.slot_begin;
  core::PixelSampling sampling;
  sampling.optimize = band.optimize;
  sampling.params = band.synergy;
  sampling.solution = k >= 0 && band.solutions != nullptr ? &band.solutions[b] : nullptr;
  const core::AnchorSet* anchors = k >= 0 ? &band.anchors[b] : nullptr;
  if (kSharesPairs) {
    core::DeformableSweepPixel(*params, col, row, iteration, anchors, band.planes, band.cost,
                               core::OwnPlaneAnchorSums{*params, band.planes, band.cost}, sampling);
  } else {
    core::DeformableSweepPixel(*params, col, row, iteration, anchors, band.planes, band.cost,
                               core::DirectAnchorSums{*params, band.cost}, sampling);
  }
}

}  // namespace

void LaunchClassify(const core::PassParams* device_params, const core::ReliabilityParams& rp,
                    uint8_t* device_classes, int width, int height) {
  ClassifyKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params, rp, device_classes);
  MSP_CUDA_CHECK_LAUNCH();
}

void LaunchFindAnchors(const core::PassParams* device_params, const DeformableBand& band, int width,
                       int iteration, unsigned long long* device_anchored) {
  if (band.row_end <= band.row_begin) return;
  FindAnchorsKernel<<<PixelGrid(width, band.row_end - band.row_begin), PixelBlock()>>>(
      device_params, band, width, iteration, device_anchored);
  MSP_CUDA_CHECK_LAUNCH();
}

void LaunchDeformableSweep(const core::PassParams* device_params, const DeformableBand& band,
                           int width, int color, int iteration, bool shares_pairs) {
  if (band.row_end <= band.row_begin) return;
  const dim3 grid = PixelGrid(width, band.row_end - band.row_begin);
  if (shares_pairs) {
    DeformableSweepKernel<true>
        <<<grid, PixelBlock()>>>(device_params, band, width, color, iteration);
  } else {
    DeformableSweepKernel<false>
        <<<grid, PixelBlock()>>>(device_params, band, width, color, iteration);
  }
  MSP_CUDA_CHECK_LAUNCH();
}

size_t MaxDeformableKernelLocalBytes() {
  return std::max({KernelLocalBytes(ClassifyKernel), KernelLocalBytes(FindAnchorsKernel),
                   KernelLocalBytes(DeformableSweepKernel<true>),
                   KernelLocalBytes(DeformableSweepKernel<false>)});
}

}  // namespace cuda
}  // namespace msp

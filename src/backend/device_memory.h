// Device memory of one reference image on the CUDA back-end, from the sizes
// of the buffers its kernels hold at once (src/backend/cuda/device_pass.h), and the check
// of every image against the free memory of the GPU it runs on, made before
// anything runs: an image that does not fit stops the run with the size that
// would, instead of failing inside a kernel.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "backend/device_query.h"
#include "base/mvs_input.h"

namespace msp {

// Bytes per reference pixel of the per-pixel state on the device: depth,
// normal (3), cost (float each) and the view mask (uint32), plus the
// reliability classes, the unlit and the held pixels (1 byte each) and the
// matching windows' regions (int32).
constexpr size_t kDeviceStateBytesPerPixel = 4 + 12 + 4 + 4 + 1 + 1 + 1 + 4;

// Bytes per reference pixel of the deformable step's whole-image maps on the
// device: the iteration's snapshot of the planes (depth, normal), the
// nearest reliable pixel and the anchor slot (int each), the confining
// edges (1 byte) and their nearest pixel (int). The anchors of the
// unreliable pixels are not counted: they go to the device in row bands
// that fit what is left (backend/row_bands.h).
constexpr size_t kDeviceDeformableBytesPerPixel = 4 + 12 + 4 + 4 + 1 + 4;

struct ImageSize {
  int width = 0;
  int height = 0;
  size_t Pixels() const { return static_cast<size_t>(width) * height; }
};

struct DeviceMemoryEstimate {
  size_t images = 0;         // grey reference and source images (float)
  size_t source_depths = 0;  // previous-pass depth of every source (geometric passes)
  size_t state = 0;          // the reference image's per-pixel state
  size_t deformable = 0;     // the deformable step's whole-image maps
  size_t params = 0;         // the pass parameters
  size_t Total() const { return images + source_depths + state + deformable + params; }
};

// The estimate for a reference image of size `ref` matched against `sources`.
DeviceMemoryEstimate EstimateDeviceMemory(const ImageSize& ref,
                                          const std::vector<ImageSize>& sources, bool geometric);

// The estimate of problem `problem` at its views' working sizes.
DeviceMemoryEstimate EstimateProblemMemory(const std::vector<View>& views, const Problem& problem,
                                           bool geometric);

// The largest value of --PatchMatchStereo.max_image_size with which
// `estimate` (made at images whose larger side is `max_side`) fits in
// `available` bytes: the buffers scale with the image area; 0 when none does.
int LargestFittingImageSize(const DeviceMemoryEstimate& estimate, int max_side, size_t available);

// Checks every problem against the device of the worker it runs on (problem
// n on worker n % workers.size()) and returns one log line per worker with
// its largest estimate and free memory. Throws std::runtime_error naming the
// image, the bytes needed and free, and the max_image_size that would fit,
// when one does not fit.
std::vector<std::string> CheckDeviceMemory(const std::vector<View>& views,
                                           const std::vector<Problem>& problems,
                                           const std::vector<DeviceInfo>& workers, bool geometric);

}  // namespace msp

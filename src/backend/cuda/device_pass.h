// One pass's inputs and per-pixel state copied to the current device: the
// grey reference and source images (plain device buffers, sampled by the
// core's own bilinear SampleBilinear, so both back-ends interpolate alike),
// the sources' previous-pass depths in a geometric pass, the state arrays,
// and the PassParams pointing at them. The buffers are the ones the memory
// estimate counts (src/backend/device_memory.h).
#pragma once

#include <cstdint>
#include <vector>

#include "backend/cuda/device_buffer.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace cuda {

class DevicePass {
 public:
  // Uploads everything `host` points at; host.state must be host memory.
  explicit DevicePass(const core::PassParams& host);
  // The device's PassParams (device memory), for the kernels.
  const core::PassParams* params() const { return params_.data(); }
  int width() const { return width_; }
  int height() const { return height_; }
  // The device state's planes (depth; normal as 3 planes of width * height).
  float* depth() const { return depth_.data(); }
  float* normal() const { return normal_.data(); }
  // Copies the device state into the host arrays of host.state.
  void DownloadState(const core::PassParams& host) const;

 private:
  // A device copy of `view` (same pitch); a view without data stays so.
  core::ImageView UploadImage(const core::ImageView& view, DeviceBuffer<float>* buffer);

  int width_ = 0;
  int height_ = 0;
  DeviceBuffer<float> ref_image_;
  std::vector<DeviceBuffer<float>> src_images_;
  std::vector<DeviceBuffer<float>> src_depths_;
  DeviceBuffer<float> depth_, normal_, cost_;
  DeviceBuffer<uint32_t> mask_;
  DeviceBuffer<uint8_t> unlit_;
  DeviceBuffer<uint8_t> held_;
  DeviceBuffer<int32_t> window_regions_;
  DeviceBuffer<core::PassParams> params_;
};

}  // namespace cuda
}  // namespace msp

#include "cuda/cuda_sweep_engine.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "cuda/cuda_check.h"
#include "cuda/device_buffer.h"
#include "cuda/device_pass.h"
#include "cuda/sweep_kernels.h"

namespace msp {
namespace cuda {
namespace {

constexpr double kBytesPerMebibyte = 1024.0 * 1024.0;

}  // namespace

CudaSweepEngine::CudaSweepEngine(std::map<uint32_t, int> device_of_image, int default_device)
    : device_of_image_(std::move(device_of_image)), default_device_(default_device) {}

void CudaSweepEngine::SelectDevice(const core::PassParams& params) {
  const auto it = device_of_image_.find(params.image_id);
  const int device = it != device_of_image_.end() ? it->second : default_device_;
  MSP_CUDA_CHECK(cudaSetDevice(device));
  if (std::find(used_devices_.begin(), used_devices_.end(), device) == used_devices_.end()) {
    used_devices_.push_back(device);
  }
}

void CudaSweepEngine::Initialize(const core::PassParams& params) {
  SelectDevice(params);
  const DevicePass pass(params);
  LaunchInitialize(pass.params(), pass.width(), pass.height());
  LaunchScore(pass.params(), pass.width(), pass.height());
  pass.DownloadState(params);
}

void CudaSweepEngine::Score(const core::PassParams& params) {
  SelectDevice(params);
  const DevicePass pass(params);
  LaunchScore(pass.params(), pass.width(), pass.height());
  pass.DownloadState(params);
}

void CudaSweepEngine::Checkerboard(const core::PassParams& params, int num_iterations) {
  SelectDevice(params);
  const DevicePass pass(params);
  for (int iteration = 0; iteration < num_iterations; ++iteration) {
    for (int color = 0; color < 2; ++color) {
      LaunchCheckerboard(pass.params(), pass.width(), pass.height(), color, iteration);
    }
  }
  pass.DownloadState(params);
}

void CudaSweepEngine::LocalRefine(const core::PassParams& params) {
  SelectDevice(params);
  const DevicePass pass(params);
  LaunchLocalRefine(pass.params(), pass.width(), pass.height());
  pass.DownloadState(params);
}

std::vector<uint8_t> CudaSweepEngine::LocalRefineAndClassify(const core::PassParams& params,
                                                             const core::ReliabilityParams& rp) {
  SelectDevice(params);
  const DevicePass pass(params);
  const size_t n = static_cast<size_t>(pass.width()) * pass.height();
  DeviceBuffer<uint8_t> classes(n);
  LaunchLocalRefineAndClassify(pass.params(), rp, classes.data(), pass.width(), pass.height());
  pass.DownloadState(params);
  std::vector<uint8_t> host(n);
  classes.Download(host.data(), n);
  return host;
}

void CudaSweepEngine::Finish() {
  for (int device : used_devices_) {
    std::printf("GPU %d: peak device memory of the run's buffers %.1f MiB\n", device,
                DeviceMemoryMeter::Peak(device) / kBytesPerMebibyte);
  }
}

}  // namespace cuda
}  // namespace msp

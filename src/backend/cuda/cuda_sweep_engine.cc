#include "backend/cuda/cuda_sweep_engine.h"

#include <cuda_runtime.h>

#include <algorithm>
#include <utility>

#include "backend/cuda/cuda_check.h"
#include "backend/cuda/deformable_kernels.h"
#include "backend/cuda/device_buffer.h"
#include "backend/cuda/device_pass.h"
#include "backend/cuda/sweep_kernels.h"
#include "base/log.h"

namespace msp {
namespace cuda {
namespace {

constexpr double kBytesPerMebibyte = 1024.0 * 1024.0;

}  // namespace

CudaSweepEngine::CudaSweepEngine(std::map<uint32_t, int> device_of_image, int default_device)
    : device_of_image_(std::move(device_of_image)), default_device_(default_device) {}

int CudaSweepEngine::ImageDevice(const core::PassParams& params) {
  const auto it = device_of_image_.find(params.image_id);
  const int device = it != device_of_image_.end() ? it->second : default_device_;
  MSP_CUDA_CHECK(cudaSetDevice(device));
  if (std::find(used_devices_.begin(), used_devices_.end(), device) == used_devices_.end()) {
    used_devices_.push_back(device);
  }
  return device;
}

template <typename Step>
void CudaSweepEngine::OnDevice(const core::PassParams& params, Step step) {
  ImageDevice(params);
  const DevicePass pass(params);
  step(pass);
  pass.DownloadState(params);
}

void CudaSweepEngine::Initialize(const core::PassParams& params) {
  OnDevice(params, [](const DevicePass& pass) {
    LaunchInitialize(pass.params(), pass.width(), pass.height());
    LaunchScore(pass.params(), pass.width(), pass.height());
  });
}

void CudaSweepEngine::Score(const core::PassParams& params) {
  OnDevice(params,
           [](const DevicePass& pass) { LaunchScore(pass.params(), pass.width(), pass.height()); });
}

void CudaSweepEngine::Checkerboard(const core::PassParams& params, int num_iterations) {
  OnDevice(params, [num_iterations](const DevicePass& pass) {
    for (int iteration = 0; iteration < num_iterations; ++iteration) {
      for (int color = 0; color < 2; ++color) {
        LaunchCheckerboard(pass.params(), pass.width(), pass.height(), color, iteration);
      }
    }
  });
}

void CudaSweepEngine::LocalRefine(const core::PassParams& params) {
  OnDevice(params, [](const DevicePass& pass) {
    LaunchLocalRefine(pass.params(), pass.width(), pass.height());
  });
}

template <typename Launch>
std::vector<uint8_t> CudaSweepEngine::ClassesOnDevice(const core::PassParams& params,
                                                      Launch launch) {
  std::vector<uint8_t> classes;
  OnDevice(params, [&](const DevicePass& pass) {
    const size_t n = static_cast<size_t>(pass.width()) * pass.height();
    DeviceBuffer<uint8_t> device_classes(n);
    launch(pass, device_classes.data());
    classes.resize(n);
    device_classes.Download(classes.data(), n);
  });
  return classes;
}

std::vector<uint8_t> CudaSweepEngine::LocalRefineAndClassify(const core::PassParams& params,
                                                             const core::ReliabilityParams& rp) {
  return ClassesOnDevice(params, [&](const DevicePass& pass, uint8_t* classes) {
    LaunchLocalRefineAndClassify(pass.params(), rp, classes, pass.width(), pass.height());
  });
}

std::vector<uint8_t> CudaSweepEngine::Classify(const core::PassParams& params,
                                               const core::ReliabilityParams& rp) {
  return ClassesOnDevice(params, [&](const DevicePass& pass, uint8_t* classes) {
    LaunchClassify(pass.params(), rp, classes, pass.width(), pass.height());
  });
}

void CudaSweepEngine::Finish() {
  for (int device : used_devices_) {
    Logf(kLogAlways, "GPU %d: peak device memory of the run's buffers %.1f MiB\n", device,
         DeviceMemoryMeter::Peak(device) / kBytesPerMebibyte);
  }
}

}  // namespace cuda
}  // namespace msp

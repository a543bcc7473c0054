// What the back-end choice needs to know about CUDA devices, behind an
// interface: the CUDA build answers with the runtime's device list and runs
// the self-check on a device (src/backend/cuda/device_query.cc), a build without CUDA
// with none, and tests with a fake list.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace msp {

struct DeviceInfo {
  int index = 0;  // CUDA device ordinal
  std::string name;
  int compute_major = 0;
  int compute_minor = 0;
  size_t total_bytes = 0;
  size_t free_bytes = 0;
  // Memory the device needs beyond the run's buffers: the kernels' local
  // memory (stack) for every resident thread, and a margin for the context.
  size_t reserve_bytes = 0;
};

// The outcome of a device's self-check (device_self_check.h): whether the
// device's kernels and the CPU core agreed on a small synthetic problem, and
// the figures (or the CUDA error) in one line.
struct SelfCheckReport {
  bool passed = false;
  std::string figures;
};

class DeviceQuery {
 public:
  virtual ~DeviceQuery() = default;
  // False when this msp_stereo was built without the CUDA back-end.
  virtual bool CudaBuilt() const = 0;
  // The devices present that can be opened; never throws. *why_none says why
  // there are none (e.g. the runtime's error for a machine without a driver)
  // and names each listed device that could not be opened.
  virtual std::vector<DeviceInfo> Devices(std::string* why_none) const = 0;
  // Runs the self-check on `device` (one of Devices()); never throws: a
  // CUDA error is a failed check whose figures name the error.
  virtual SelfCheckReport SelfCheck(const DeviceInfo& device) const = 0;
};

// The query of this build: CUDA's runtime in a CUDA build, else one that
// reports no CUDA back-end.
std::unique_ptr<DeviceQuery> MakeDeviceQuery();

}  // namespace msp

// --MspStereo.backend auto|cpu|cuda and --PatchMatchStereo.gpu_index turned
// into the back-end that runs and its workers (one per listed GPU).
#pragma once

#include <string>
#include <vector>

#include "backend/device_query.h"

namespace msp {

struct BackendChoice {
  std::string backend;              // "cpu" or "cuda"
  std::vector<DeviceInfo> workers;  // cuda: one per entry of gpu_index
  std::string reason;               // why, for the log
};

// auto: cuda when this build has it and a device is present, else cpu.
// cpu: cpu (gpu_index is not read). cuda: cuda, or std::runtime_error naming
// the option when the build has no CUDA back-end or no device is found.
// With cuda chosen, a bad gpu_index throws std::invalid_argument
// (ParseGpuIndex).
BackendChoice ChooseBackend(const std::string& backend, const std::string& gpu_index,
                            const DeviceQuery& query);

// One log line: the back-end that runs, why, and its devices.
std::string DescribeChoice(const BackendChoice& choice);

}  // namespace msp

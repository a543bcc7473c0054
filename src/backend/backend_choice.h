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
  // cuda: one line per device self-checked, with the check's figures.
  std::vector<std::string> self_checks;
};

// auto: cuda when this build has it, a device is present and every device
// of gpu_index passes its self-check (DeviceQuery::SelfCheck), else cpu with
// the reason. cpu: cpu (gpu_index is not read, no device is asked). cuda:
// cuda, or std::runtime_error naming the option when the build has no CUDA
// back-end, no device is found, or a device fails its self-check (with the
// check's figures). With cuda chosen, a bad gpu_index throws
// std::invalid_argument (ParseGpuIndex).
BackendChoice ChooseBackend(const std::string& backend, const std::string& gpu_index,
                            const DeviceQuery& query);

// One log line: the back-end that runs, why, and its devices.
std::string DescribeChoice(const BackendChoice& choice);

}  // namespace msp

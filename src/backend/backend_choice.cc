#include "backend/backend_choice.h"

#include <set>
#include <sstream>
#include <stdexcept>

#include "backend/gpu_index.h"
#include "options/option_name.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

constexpr double kBytesPerMebibyte = 1024.0 * 1024.0;

std::string BackendFlag() { return MSP_OPTION_FLAG_OF(MspStereoOptions, backend); }

BackendChoice CpuChoice(const std::string& reason) {
  BackendChoice choice;
  choice.backend = "cpu";
  choice.reason = reason;
  return choice;
}

}  // namespace

BackendChoice ChooseBackend(const std::string& backend, const std::string& gpu_index,
                            const DeviceQuery& query) {
  if (backend == "cpu") return CpuChoice("requested");
  if (backend != "auto" && backend != "cuda") {
    throw std::invalid_argument(BackendFlag() + ": unknown back-end \"" + backend + "\"");
  }
  const bool required = backend == "cuda";
  if (!query.CudaBuilt()) {
    const std::string why =
        "this msp_stereo was built without the CUDA back-end (nvcc not found or "
        "-DCUDA_ENABLED=OFF)";
    if (required)
      throw std::runtime_error(BackendFlag() + " cuda: " + why + "; use " + BackendFlag() +
                               " cpu or auto");
    return CpuChoice("auto: " + why);
  }
  std::string why_none;
  const std::vector<DeviceInfo> devices = query.Devices(&why_none);
  if (devices.empty()) {
    const std::string why =
        "no CUDA device found" + (why_none.empty() ? "" : " (" + why_none + ")");
    if (required)
      throw std::runtime_error(BackendFlag() + " cuda: " + why + "; use " + BackendFlag() +
                               " cpu or auto");
    return CpuChoice("auto: " + why);
  }
  BackendChoice choice;
  choice.backend = "cuda";
  choice.reason = required ? "requested" : "auto: CUDA device found";
  for (int d : ParseGpuIndex(gpu_index, static_cast<int>(devices.size()))) {
    choice.workers.push_back(devices[d]);
  }
  // No device is trusted before its kernels have agreed with the CPU core
  // on the self-check's problem: once per device the workers use.
  std::set<int> checked;
  for (const DeviceInfo& d : choice.workers) {
    if (!checked.insert(d.index).second) continue;
    const SelfCheckReport check = query.SelfCheck(d);
    const std::string device = "GPU " + std::to_string(d.index) + " " + d.name;
    if (check.passed) {
      choice.self_checks.push_back("Self-check of " + device + ": " + check.figures);
      continue;
    }
    const std::string why =
        device + " failed its self-check against the CPU core: " + check.figures;
    if (required) {
      throw std::runtime_error(BackendFlag() + " cuda: " + why + "; use " + BackendFlag() +
                               " cpu, and run bench/gpu_check.sh on this machine");
    }
    return CpuChoice("auto: " + why + "; running on the CPU");
  }
  choice.reason += ", self-check against the CPU core passed";
  return choice;
}

std::string DescribeChoice(const BackendChoice& choice) {
  std::ostringstream out;
  out << "Back-end: " << choice.backend << " (" << choice.reason << ")";
  for (size_t w = 0; w < choice.workers.size(); ++w) {
    const DeviceInfo& d = choice.workers[w];
    out << (w == 0 ? "; " : ", ") << "worker " << w << " on GPU " << d.index << " " << d.name
        << " (compute " << d.compute_major << "." << d.compute_minor << ", "
        << static_cast<long long>(d.free_bytes / kBytesPerMebibyte) << " of "
        << static_cast<long long>(d.total_bytes / kBytesPerMebibyte) << " MiB free)";
  }
  return out.str();
}

}  // namespace msp

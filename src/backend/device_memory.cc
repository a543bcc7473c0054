#include "backend/device_memory.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/patch_match/patch_match_kernel.h"
#include "options/option_name.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

constexpr double kBytesPerMebibyte = 1024.0 * 1024.0;

long long Mebibytes(size_t bytes) { return std::llround(bytes / kBytesPerMebibyte); }

}  // namespace

DeviceMemoryEstimate EstimateDeviceMemory(const ImageSize& ref,
                                          const std::vector<ImageSize>& sources, bool geometric) {
  DeviceMemoryEstimate e;
  e.images = ref.Pixels() * sizeof(float);
  const size_t num_sources = std::min(sources.size(), static_cast<size_t>(core::kMaxSourceViews));
  for (size_t j = 0; j < num_sources; ++j) {
    e.images += sources[j].Pixels() * sizeof(float);
    if (geometric) e.source_depths += sources[j].Pixels() * sizeof(float);
  }
  e.state = ref.Pixels() * kDeviceStateBytesPerPixel;
  e.deformable = ref.Pixels() * kDeviceDeformableBytesPerPixel;
  e.params = sizeof(core::PassParams);
  return e;
}

DeviceMemoryEstimate EstimateProblemMemory(const std::vector<View>& views, const Problem& problem,
                                           bool geometric) {
  const core::Camera& ref = views[problem.ref].camera;
  std::vector<ImageSize> sources;
  for (int v : problem.srcs) sources.push_back({views[v].camera.width, views[v].camera.height});
  return EstimateDeviceMemory({ref.width, ref.height}, sources, geometric);
}

int LargestFittingImageSize(const DeviceMemoryEstimate& estimate, int max_side, size_t available) {
  const size_t scaled = estimate.Total() - estimate.params;
  if (available <= estimate.params || scaled == 0) return 0;
  // Buffers scale with the area, i.e. with the square of the side.
  const double ratio = static_cast<double>(available - estimate.params) / scaled;
  const int side = static_cast<int>(std::floor(max_side * std::sqrt(std::min(ratio, 1.0))));
  return std::max(side, 0);
}

std::vector<std::string> CheckDeviceMemory(const std::vector<View>& views,
                                           const std::vector<Problem>& problems,
                                           const std::vector<DeviceInfo>& workers, bool geometric) {
  if (workers.empty()) throw std::invalid_argument("CheckDeviceMemory: no worker");
  std::vector<size_t> largest(workers.size(), 0);
  for (size_t n = 0; n < problems.size(); ++n) {
    const DeviceInfo& device = workers[n % workers.size()];
    const DeviceMemoryEstimate e = EstimateProblemMemory(views, problems[n], geometric);
    largest[n % workers.size()] = std::max(largest[n % workers.size()], e.Total());
    const size_t available =
        device.free_bytes > device.reserve_bytes ? device.free_bytes - device.reserve_bytes : 0;
    if (e.Total() <= available) continue;
    int max_side = 0;
    for (int v : problems[n].srcs) {
      max_side = std::max({max_side, views[v].camera.width, views[v].camera.height});
    }
    const core::Camera& ref = views[problems[n].ref].camera;
    max_side = std::max({max_side, ref.width, ref.height});
    std::ostringstream msg;
    msg << "image " << views[problems[n].ref].name << " (" << ref.width << "x" << ref.height << ", "
        << problems[n].srcs.size() << " sources) needs about " << Mebibytes(e.Total())
        << " MiB of device memory, GPU " << device.index << " (" << device.name << ") has "
        << Mebibytes(available) << " MiB free beyond the " << Mebibytes(device.reserve_bytes)
        << " MiB its kernels and context reserve";
    const int fits = LargestFittingImageSize(e, max_side, available);
    if (fits > 0) {
      msg << "; run with " << MSP_OPTION_FLAG_OF(PatchMatchStereoOptions, max_image_size) << " "
          << fits << " or less, or with " << MSP_OPTION_FLAG_OF(MspStereoOptions, backend)
          << " cpu";
    } else {
      msg << "; run with " << MSP_OPTION_FLAG_OF(MspStereoOptions, backend) << " cpu";
    }
    throw std::runtime_error(msg.str());
  }
  std::vector<std::string> lines;
  for (size_t w = 0; w < workers.size(); ++w) {
    std::ostringstream line;
    line << "Device memory estimate, worker " << w << " (GPU " << workers[w].index << "): up to "
         << Mebibytes(largest[w]) << " MiB per image, " << Mebibytes(workers[w].free_bytes)
         << " MiB free, " << Mebibytes(workers[w].reserve_bytes)
         << " MiB reserved for kernels and context";
    lines.push_back(line.str());
  }
  return lines;
}

}  // namespace msp

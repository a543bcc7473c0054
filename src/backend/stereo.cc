#include "backend/stereo.h"

#include <stdexcept>

#include "backend/backend_choice.h"
#include "backend/cpu/cpu_entry.h"
#include "backend/cuda/cuda_entry.h"
#include "backend/device_memory.h"
#include "base/log.h"

namespace msp {

BackendChoice ChooseStereoBackend(const PatchMatchStereoOptions& patch_match,
                                  const MspStereoOptions& msp) {
  const std::unique_ptr<DeviceQuery> query = MakeDeviceQuery();
  return ChooseBackend(msp.backend, patch_match.gpu_index, *query);
}

void RunStereo(const BackendChoice& choice, const std::vector<View>& views,
               const std::vector<Problem>& problems, const PatchMatchStereoOptions& patch_match,
               const MspStereoOptions& msp, const std::string& scratch_dir, MapSink& sink,
               const SharedRun* shared) {
  LogText(kLogAlways, DescribeChoice(choice) + "\n");
  for (const std::string& line : choice.self_checks) LogText(kLogAlways, line + "\n");
  if (choice.backend == "cpu") {
    RunPatchMatchCpu(views, problems, patch_match, msp, scratch_dir, sink, shared);
    return;
  }
  // Before anything runs: an image that cannot fit stops here, not in a kernel.
  for (const std::string& line :
       CheckDeviceMemory(views, problems, choice.workers, patch_match.geom_consistency)) {
    LogText(kLogAlways, line + "\n");
  }
  RunPatchMatchCuda(views, problems, patch_match, msp, scratch_dir, sink, choice.workers, shared);
}

}  // namespace msp

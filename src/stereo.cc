#include "stereo.h"

#include <stdexcept>

#include "backend/backend_choice.h"
#include "backend/cuda_entry.h"
#include "backend/device_memory.h"
#include "base/log.h"
#include "patch_match/patch_match_cpu.h"

namespace msp {
namespace {

BackendChoice ResolveBackend(const PatchMatchStereoOptions& patch_match,
                             const MspStereoOptions& msp) {
  const std::unique_ptr<DeviceQuery> query = MakeDeviceQuery();
  return ChooseBackend(msp.backend, patch_match.gpu_index, *query);
}

}  // namespace

void CheckBackendCanRun(const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp) {
  ResolveBackend(patch_match, msp);
}

void RunStereo(const std::vector<View>& views, const std::vector<Problem>& problems,
               const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
               const std::string& scratch_dir, MapSink& sink, const SharedRun* shared) {
  const BackendChoice choice = ResolveBackend(patch_match, msp);
  LogText(kLogAlways, DescribeChoice(choice) + "\n");
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

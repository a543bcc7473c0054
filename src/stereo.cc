#include "stereo.h"

#include <stdexcept>

#include "options/option_name.h"
#include "patch_match/patch_match_cpu.h"

namespace msp {

void CheckBackendCanRun(const MspStereoOptions& msp) {
  if (msp.backend == "cuda") {
    const std::string backend = MSP_OPTION_FLAG(msp, backend);
    throw std::runtime_error(backend + " cuda: the CUDA back-end cannot run patch match yet; use " +
                             backend + " cpu");
  }
}

void RunStereo(const std::vector<View>& views, const std::vector<Problem>& problems,
               const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
               const std::string& scratch_dir, MapSink& sink) {
  CheckBackendCanRun(msp);
  RunPatchMatchCpu(views, problems, patch_match, msp, scratch_dir, sink);
}

}  // namespace msp

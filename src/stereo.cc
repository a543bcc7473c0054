#include "stereo.h"

#include <stdexcept>

#include "patch_match/patch_match_cpu.h"

namespace msp {

void RunStereo(const std::vector<View>& views, const std::vector<Problem>& problems,
               const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
               const std::string& scratch_dir, MapSink& sink) {
  if (msp.backend == "cuda") {
    throw std::runtime_error(
        "--MspStereo.backend cuda: the CUDA back-end cannot run patch match yet in this "
        "version; use --MspStereo.backend cpu");
  }
  RunPatchMatchCpu(views, problems, patch_match, msp, scratch_dir, sink);
}

}  // namespace msp

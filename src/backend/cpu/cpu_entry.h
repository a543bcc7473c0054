// The CPU back-end's entry point: the pass runner with the CPU's sweep engine.
#pragma once

#include <string>
#include <vector>

#include "base/mvs_input.h"
#include "options/stereo_options.h"
#include "patch_match/map_sink.h"
#include "patch_match/pass_exchange.h"

namespace msp {

// RunPatchMatch (patch_match/pass_runner.h) with the CPU's sweeps, on
// --PatchMatchStereo.num_threads threads.
void RunPatchMatchCpu(const std::vector<View>& views, const std::vector<Problem>& problems,
                      const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
                      const std::string& scratch_dir, MapSink& sink,
                      const SharedRun* shared = nullptr);

}  // namespace msp

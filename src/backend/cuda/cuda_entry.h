// The CUDA back-end's entry point: defined in cuda_entry.cc when nvcc built it, else
// by no_cuda.cc (which also gives the query that reports no CUDA).
#pragma once

#include <string>
#include <vector>

#include "backend/device_query.h"
#include "base/mvs_input.h"
#include "options/stereo_options.h"
#include "patch_match/map_sink.h"
#include "patch_match/pass_exchange.h"

namespace msp {

// The pass schedule with the CUDA kernels' sweeps, problem n on workers[n %
// workers.size()].
void RunPatchMatchCuda(const std::vector<View>& views, const std::vector<Problem>& problems,
                       const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
                       const std::string& scratch_dir, MapSink& sink,
                       const std::vector<DeviceInfo>& workers, const SharedRun* shared = nullptr);

}  // namespace msp

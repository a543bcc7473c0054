// RunPatchMatchCuda: the CPU back-end's pass schedule with the GPU's sweeps.
#include "backend/cuda/cuda_entry.h"

#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "backend/cuda/cuda_sweep_engine.h"
#include "backend/gpu_index.h"
#include "base/log.h"
#include "patch_match/pass_runner.h"

namespace msp {

void RunPatchMatchCuda(const std::vector<View>& views, const std::vector<Problem>& problems,
                       const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
                       const std::string& scratch_dir, MapSink& sink,
                       const std::vector<DeviceInfo>& workers, const SharedRun* shared) {
  if (workers.empty()) throw std::invalid_argument("RunPatchMatchCuda: no GPU worker");
  // Problem n on worker n % k, as CheckDeviceMemory assumed.
  std::map<uint32_t, int> device_of_image;
  const std::vector<std::vector<int>> spread =
      SpreadOverWorkers(static_cast<int>(problems.size()), static_cast<int>(workers.size()));
  for (size_t w = 0; w < spread.size(); ++w) {
    for (int n : spread[w]) {
      device_of_image[static_cast<uint32_t>(problems[n].ref)] = workers[w].index;
    }
  }
  Logf(kLogAlways,
       "CUDA back-end: random initialisation, scoring, red-black sweeps, the local refinement and "
       "the deformable step's classification, anchor searches and sweeps run on the GPU; the "
       "nearest reliable pixels, the median filter, segment planes, the segmentation prior, "
       "upsampling and the output filter run on the CPU with %s threads\n",
       msp.num_threads > 0 ? std::to_string(msp.num_threads).c_str() : "all");
  cuda::CudaSweepEngine engine(std::move(device_of_image), workers.front().index);
  RunPatchMatch(views, problems, patch_match, msp, scratch_dir, sink, engine, shared);
}

}  // namespace msp

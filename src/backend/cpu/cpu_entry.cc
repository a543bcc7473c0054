#include "backend/cpu/cpu_entry.h"

#include "backend/cpu/cpu_sweep_engine.h"
#include "base/parallel_for.h"
#include "patch_match/pass_runner.h"

namespace msp {

void RunPatchMatchCpu(const std::vector<View>& views, const std::vector<Problem>& problems,
                      const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
                      const std::string& scratch_dir, MapSink& sink, const SharedRun* shared) {
  CpuSweepEngine engine(ResolveNumThreads(msp.num_threads));
  RunPatchMatch(views, problems, patch_match, msp, scratch_dir, sink, engine, shared);
}

}  // namespace msp

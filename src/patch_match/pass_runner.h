// The pass runner of both back-ends: walks the APD pass schedule
// (engine/pass_schedule.h: coarse-to-fine rounds, each one photometric pass
// and, with geom_consistency, three geometric passes) over all problems, with
// the per-pixel sweeps of a back-end's engine (engine/sweep_engine.h) and the
// whole-image steps between them (segment planes, open sky, the output filter)
// on the CPU.
#pragma once

#include <string>
#include <vector>

#include "base/mvs_input.h"
#include "engine/sweep_engine.h"
#include "options/stereo_options.h"
#include "patch_match/map_sink.h"
#include "patch_match/pass_exchange.h"

namespace msp {

// The schedule with the per-pixel sweeps of `engine` (the other steps of a
// pass run on the CPU with --PatchMatchStereo.num_threads threads). With `shared`,
// this process computes only shared->owned and meets the other processes of
// the run at a barrier after every pass (shared_passes.h).
void RunPatchMatch(const std::vector<View>& views, const std::vector<Problem>& problems,
                   const PatchMatchStereoOptions& patch_match, const MspStereoOptions& msp,
                   const std::string& scratch_dir, MapSink& sink, SweepEngine& engine,
                   const SharedRun* shared = nullptr);

}  // namespace msp

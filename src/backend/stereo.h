// Entry point of the stereo back-ends: runs every problem through the pass
// schedule and hands finished maps to a sink. Knows nothing of files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/dense_map.h"
#include "base/mvs_input.h"
#include "options/stereo_options.h"
#include "patch_match/map_sink.h"
#include "patch_match/pass_exchange.h"

namespace msp {

struct BackendChoice;  // backend/backend_choice.h

// The back-end --MspStereo.backend chooses (auto: CUDA when a device is
// present and passes its self-check, else the CPU; the choice's reason says
// which and why). Throws std::runtime_error when the back-end of
// --MspStereo.backend cuda cannot run (no CUDA build, no device, or a device
// failing its self-check), std::invalid_argument for a bad
// --PatchMatchStereo.gpu_index; a command calls it once, before writing
// anything, so that nothing partial is left behind.
BackendChoice ChooseStereoBackend(const PatchMatchStereoOptions& patch_match,
                                  const MspStereoOptions& msp);

// Runs every problem on the back-end of `choice` (ChooseStereoBackend; the log
// says which). `scratch_dir` is where per-image state may be spilled when it
// exceeds --PatchMatchStereo.cache_size. Throws std::runtime_error when an
// image does not fit its GPU's free memory (CheckDeviceMemory), before
// anything runs. With `shared`, this process is one of several that share
// the run's passes (patch_match/pass_exchange.h) and computes only
// shared->owned.
void RunStereo(const BackendChoice& choice, const std::vector<View>& views,
               const std::vector<Problem>& problems, const PatchMatchStereoOptions& patch_match,
               const MspStereoOptions& msp, const std::string& scratch_dir, MapSink& sink,
               const SharedRun* shared = nullptr);

}  // namespace msp

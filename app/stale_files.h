// What a killed run leaves in stereo/: temporary files of atomic writes
// ("<name>.tmp-<pid>", file_util.h) and spilled per-image state
// ("msp/state-<pid>-<view>.bin", patch_match/state_cache.h). None of them is
// ever taken for output, but they take disk space; msp_stereo removes them at
// start, while it holds the workspace lock, so none belongs to a live run.
#pragma once

#include <string>
#include <vector>

namespace msp {

// True for "<anything>.tmp-<digits>".
bool IsTemporaryFileName(const std::string& file_name);
// True for "state-<digits>-<digits>.bin".
bool IsSpilledStateFileName(const std::string& file_name);

// Removes temporary files anywhere under `stereo_dir` and spilled state files
// directly in `scratch_dir`; returns their paths. Files that cannot be removed
// are left (the run does not need them gone).
std::vector<std::string> RemoveStaleFiles(const std::string& stereo_dir,
                                          const std::string& scratch_dir);

}  // namespace msp

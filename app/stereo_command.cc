// The msp_stereo command without its command line (stereo_command.h): the
// msp_stereo program and the Python module both run it, so that the same
// options give the same maps and the same log.

#include "app/stereo_command.h"

#include <chrono>
#include <exception>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/shard_setup.h"
#include "app/shared_pass_dir.h"
#include "app/stale_files.h"
#include "app/workspace_lock.h"
#include "backend/backend_choice.h"
#include "backend/stereo.h"
#include "base/log.h"
#include "base/stop_request.h"
#include "engine/pass_schedule.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/ground_truth.h"
#include "io/map_writer.h"
#include "io/workspace.h"
#include "options/option_check.h"
#include "options/option_name.h"
#include "options/option_parser.h"
#include "options/shard_spec.h"

namespace msp {
namespace {

// Per-run scratch space (spilled per-image state), inside the workspace so
// it lives on the same disk as the maps.
constexpr char kScratchSubdir[] = "/stereo/msp";

void PrintHeading(const std::string& heading) {
  const std::string rule(78, '=');
  LogText(kLogAlways, "\n" + rule + "\n" + heading + "\n" + rule + "\n\n");
}

// Options accepted for COLMAP compatibility that this build does not honour;
// said once at start-up so nobody wonders why they had no effect. Option
// names are spelt from their fields (option_name.h).
void WarnAboutIgnoredOptions(const StereoCommandOptions& options) {
  const PatchMatchStereoOptions& p = options.patch_match;
  const MspStereoOptions& m = options.msp;
  const PatchMatchStereoOptions defaults;
  if (p.write_consistency_graph) {
    LogWarning(MSP_OPTION_FLAG(p, write_consistency_graph) +
               " is ignored: no consistency graphs are written (no COLMAP command reads them)");
  }
  if (p.window_step != defaults.window_step) {
    LogWarning(MSP_OPTION_FLAG(p, window_step) + " is ignored (the window sampling step is " +
               MSP_OPTION_FLAG(m, window_step) + ")");
  }
  if (!m.bilateral_ncc &&
      (p.sigma_spatial != defaults.sigma_spatial || p.sigma_color != defaults.sigma_color)) {
    LogWarning(MSP_OPTION_FLAG(p, sigma_spatial) + " / " + MSP_OPTION_FLAG(p, sigma_color) +
               " only apply with " + MSP_OPTION_FLAG(m, bilateral_ncc) + " true");
  }
  if (p.geom_consistency_regularizer != defaults.geom_consistency_regularizer &&
      m.geom_consistency_depth_error > 0.0) {
    LogWarning(MSP_OPTION_FLAG(p, geom_consistency_regularizer) + " only applies with " +
               MSP_OPTION_FLAG(m, geom_consistency_depth_error) +
               " 0 (the term in pixels); the term in depth takes " +
               MSP_OPTION_FLAG(m, geom_consistency_depth_weight));
  }
  if (p.num_iterations != defaults.num_iterations) {
    LogWarning(MSP_OPTION_FLAG(p, num_iterations) + " is ignored (the APD schedule runs " +
               MSP_OPTION_FLAG(m, advanced_iterations) +
               " red-black iterations per pass: one photometric pass and, with " +
               MSP_OPTION_FLAG(p, geom_consistency) + ", " +
               MSP_OPTION_FLAG(m, advanced_geometric_passes) + " geometric passes per round)");
  }
  if (p.ncc_sigma != defaults.ncc_sigma ||
      p.incident_angle_sigma != defaults.incident_angle_sigma) {
    LogWarning(MSP_OPTION_FLAG(p, ncc_sigma) + " / " + MSP_OPTION_FLAG(p, incident_angle_sigma) +
               " are ignored (view selection follows ACMM, not COLMAP's likelihood model)");
  }
  // Without deformable patches the prior's only use is the mask files, which
  // bound the matching windows, the segment planes and the consensus planes.
  if (m.segmentation_prior && !m.deformable &&
      !(m.region_windows || m.segment_planes || m.consensus_planes)) {
    LogWarning(MSP_OPTION_FLAG(m, segmentation_prior) + " has no effect without " +
               MSP_OPTION_FLAG(m, deformable) + " or a step that mask files bound (" +
               MSP_OPTION_FLAG(m, region_windows) + ", " + MSP_OPTION_FLAG(m, segment_planes) +
               ", " + MSP_OPTION_FLAG(m, consensus_planes) + ")");
  }
  if (m.write_previews && !(m.segmentation_prior && m.deformable)) {
    LogWarning(MSP_OPTION_FLAG(m, write_previews) +
               " writes no prior previews: the segmentation prior does not run (the depth, "
               "normal and error previews are written)");
  }
  if (m.backend == "cpu" && p.gpu_index != defaults.gpu_index) {
    LogWarning(MSP_OPTION_FLAG(p, gpu_index) + " is ignored by the cpu back-end");
  }
}

// The ground truth the error previews compare with: <workspace>/ground_truth
// when it is there (the bundled scene). One that cannot be read costs the
// error previews, not the run.
std::optional<GroundTruthInfo> PreviewGroundTruth(const std::string& workspace_path) {
  const std::string dir = GroundTruthDir(workspace_path, "");
  if (!IsDirectory(dir)) return std::nullopt;
  try {
    GroundTruthInfo info = ReadGroundTruthInfo(dir);
    LogText(kLogAlways, "Error previews against the ground truth in " + dir + "\n");
    return info;
  } catch (const InputError& e) {
    LogWarning(std::string("no error previews: ") + e.what());
    return std::nullopt;
  }
}

// Spilled state of this process: a shard's in a folder of its own, which its
// lock keeps to itself.
std::string ScratchDir(const std::string& workspace_path, const MspStereoOptions& msp) {
  const std::string scratch = workspace_path + kScratchSubdir;
  return IsSharded(msp) ? JoinPaths(scratch, ShardTag(msp)) : scratch;
}

using Locks = std::vector<std::unique_ptr<WorkspaceLock>>;

// Takes the workspace lock (one msp_stereo per workspace; a shard shares it
// with the other shards and holds its shard's own) and removes what an
// interrupted run left behind, which no live run can own while the lock is
// held: a shard only its own spilled state, since the other shards write
// beside it.
Locks LockWorkspace(const std::string& workspace_path, const MspStereoOptions& msp) {
  const std::string stereo_dir = JoinPaths(workspace_path, "stereo");
  Locks locks;
  const bool sharded = IsSharded(msp);
  locks.push_back(std::make_unique<WorkspaceLock>(
      stereo_dir, kWorkspaceLockName, sharded ? LockMode::kShared : LockMode::kExclusive));
  if (sharded) {
    locks.push_back(
        std::make_unique<WorkspaceLock>(stereo_dir, "msp_stereo." + ShardTag(msp) + ".lock"));
  }
  const std::vector<std::string> removed =
      RemoveStaleFiles(sharded ? "" : stereo_dir, ScratchDir(workspace_path, msp));
  if (!removed.empty()) {
    LogStream() << "Removed " << removed.size()
                << " temporary file(s) an interrupted run left, e.g. " << removed.front() << "\n";
  }
  return locks;
}

// How many reference images have their final maps: what a stopped or failed
// run leaves done, and what the next run skips.
std::string WhatIsDone(const Workspace& workspace, const MapWriter& writer) {
  size_t done = 0;
  for (const Problem& problem : workspace.problems) done += writer.HasFinalOutput(problem.ref);
  return std::to_string(done) + " of " + std::to_string(workspace.problems.size()) +
         " reference images have their final maps in " + workspace.path +
         "/stereo; run the same command again to resume (finished images are skipped)";
}

// Everything after the options' check; `stop_reported` is set when a stop
// request has been said in the log (between two steps of the stereo run).
void RunChecked(const StereoCommandOptions& options, bool* stop_reported) {
  const auto start = std::chrono::steady_clock::now();
  PrintHeading("MSP stereo (backend: " + options.msp.backend + ")");
  std::ostringstream options_text;
  PrintStereoCommandOptions(options, options_text);
  LogText(kLogAlways, "Options:\n" + options_text.str() + "\n");
  WarnAboutIgnoredOptions(options);

  // Before reading: a second run on the workspace stops at once. A workspace
  // without stereo/ (possible with --config_path) is locked once it has read;
  // a back-end that cannot run reads it and stops without creating the lock.
  // The back-end is chosen once: a CUDA device's self-check runs here.
  std::optional<BackendChoice> backend;
  std::exception_ptr backend_error;
  try {
    backend = ChooseStereoBackend(options.patch_match, options.msp);
  } catch (const std::runtime_error&) {
    backend_error = std::current_exception();
  }
  Locks locks;
  if (backend && IsDirectory(JoinPaths(options.workspace_path, "stereo"))) {
    locks = LockWorkspace(options.workspace_path, options.msp);
  }
  LogText(kLogAlways, "Reading workspace " + options.workspace_path + "...\n");
  const Workspace workspace = LoadWorkspace(options);
  LogStream() << "  " << workspace.views.size() << " images, " << workspace.problems.size()
              << " problems\n";
  // Before the first file is written: a back-end that cannot run leaves the
  // workspace as it was.
  if (backend_error) std::rethrow_exception(backend_error);
  if (locks.empty()) locks = LockWorkspace(workspace.path, options.msp);
  WriteFusionConfigIfMissing(workspace);

  std::vector<std::string> names;
  names.reserve(workspace.views.size());
  for (const View& view : workspace.views) names.push_back(view.name);
  MapWriter writer(workspace.path, names, options.patch_match.geom_consistency,
                   options.msp.write_previews ? PreviewGroundTruth(workspace.path) : std::nullopt);

  // A shard: its problems, and the other shards' states in the workspace.
  std::unique_ptr<SharedPassDir> shared_dir;
  std::unique_ptr<SharedRun> shared;
  if (IsSharded(options.msp)) {
    shared.reset(new SharedRun);
    shared->owned = OwnedProblems(options.msp, workspace);
    shared_dir.reset(new SharedPassDir(SharedPassDirPath(JoinPaths(workspace.path, "stereo")),
                                       names, SharedRunFingerprint(options, workspace)));
    shared->exchange = shared_dir.get();
    if (!options.msp.shard.empty()) shared->shard = ParseShardSpec(options.msp.shard);
    shared->timeout_seconds = options.msp.shard_timeout;
    shared->name = ShardName(options.msp);
    LogStream() << shared->name << ": " << shared->owned.size() << " of "
                << workspace.problems.size() << " reference images; pass states in "
                << shared_dir->Where() << "\n";
  }

  try {
    RunStereo(*backend, workspace.views, workspace.problems, options.patch_match, options.msp,
              ScratchDir(workspace.path, options.msp), writer, shared.get());
  } catch (const StopRequested& stop) {
    const std::string message = "Stopped by " + SignalName(stop.signal_number()) +
                                " between two steps; nothing is half-written. " +
                                WhatIsDone(workspace, writer);
    LogText(kLogAlways, message + "\n");
    *stop_reported = true;
    throw StopRequested(stop.signal_number(), message);
  } catch (const std::exception&) {
    LogText(kLogAlways, WhatIsDone(workspace, writer) + "\n");
    throw;
  }

  const double minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
  LogStream() << "Elapsed time: " << std::fixed << std::setprecision(3) << minutes
              << " [minutes]\n";
}

}  // namespace

void RunStereoCommand(const StereoCommandOptions& options) {
  CheckStereoCommandOptions(options);
  SetLogLevel(options.log_level);
  bool stop_reported = false;
  try {
    RunChecked(options, &stop_reported);
  } catch (const StopRequested& stop) {
    if (stop_reported) throw;
    const std::string message =
        "Stopped by " + SignalName(stop.signal_number()) + " before any map was computed";
    LogText(kLogAlways, message + "\n");
    throw StopRequested(stop.signal_number(), message);
  }
}

}  // namespace msp

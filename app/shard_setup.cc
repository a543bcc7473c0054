#include "app/shard_setup.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "io/errors.h"
#include "io/file_util.h"
#include "options/option_name.h"
#include "options/option_parser.h"
#include "options/shard_spec.h"

namespace msp {
namespace {

std::string Trim(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

// Options that leave the maps as they are: where things are, how many
// threads, the log, which share of the images, the pictures beside the maps.
bool LeavesResultsAlone(const std::string& name) {
  static const std::set<std::string> kNames = {
      MSP_OPTION_NAME_OF(StereoCommandOptions, workspace_path),
      MSP_OPTION_NAME_OF(StereoCommandOptions, config_path),
      MSP_OPTION_NAME_OF(StereoCommandOptions, project_path),
      MSP_OPTION_NAME_OF(StereoCommandOptions, log_level),
      MSP_OPTION_NAME_OF(StereoCommandOptions, log_to_stderr),
      MSP_OPTION_NAME_OF(PatchMatchStereoOptions, gpu_index),
      MSP_OPTION_NAME_OF(PatchMatchStereoOptions, cache_size),
      MSP_OPTION_NAME_OF(PatchMatchStereoOptions, num_threads),
      MSP_OPTION_NAME_OF(MspStereoOptions, shard),
      MSP_OPTION_NAME_OF(MspStereoOptions, image_list),
      MSP_OPTION_NAME_OF(MspStereoOptions, shard_timeout),
      MSP_OPTION_NAME_OF(MspStereoOptions, write_previews),
  };
  return kNames.count(name) > 0;
}

}  // namespace

bool IsSharded(const MspStereoOptions& msp) {
  return !msp.shard.empty() || !msp.image_list.empty();
}

std::string ShardName(const MspStereoOptions& msp) {
  if (!msp.shard.empty()) return "shard " + ToString(ParseShardSpec(msp.shard));
  return "image list " + msp.image_list;
}

std::string ShardTag(const MspStereoOptions& msp) {
  if (!msp.shard.empty()) {
    const ShardSpec shard = ParseShardSpec(msp.shard);
    return "shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count);
  }
  return "list-" + std::filesystem::path(msp.image_list).filename().string();
}

std::vector<int> ReadImageList(const std::string& path, const Workspace& workspace) {
  const std::string flag = MSP_OPTION_FLAG_OF(MspStereoOptions, image_list);
  std::istringstream lines(ReadFileToString(path));
  std::set<int> owned;
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string name = Trim(line);
    if (name.empty() || name[0] == '#') continue;
    int found = -1;
    for (size_t k = 0; k < workspace.problems.size() && found < 0; ++k) {
      if (workspace.views[workspace.problems[k].ref].name == name) found = static_cast<int>(k);
    }
    if (found < 0) {
      throw InputError(flag + " " + path + " line " + std::to_string(number) + ": `" + name +
                       "` is not the reference image of any problem of the workspace (names as "
                       "in images/ and stereo/patch-match.cfg)");
    }
    owned.insert(found);
  }
  if (owned.empty()) throw InputError(flag + " " + path + " names no image");
  return std::vector<int>(owned.begin(), owned.end());
}

std::vector<int> OwnedProblems(const MspStereoOptions& msp, const Workspace& workspace) {
  if (!msp.image_list.empty()) return ReadImageList(msp.image_list, workspace);
  return ProblemsOfShard(static_cast<int>(workspace.problems.size()), ParseShardSpec(msp.shard));
}

std::string SharedRunFingerprint(const StereoCommandOptions& options, const Workspace& workspace) {
  std::ostringstream printed;
  PrintStereoCommandOptions(options, printed);
  std::istringstream lines(printed.str());
  std::string fingerprint, line;
  while (std::getline(lines, line)) {
    const std::string name = line.substr(2, line.find(' ') - 2);  // after "--"
    if (!LeavesResultsAlone(name)) fingerprint += line + "\n";
  }
  for (const Problem& problem : workspace.problems) {
    fingerprint += "problem " + workspace.views[problem.ref].name + " <-";
    for (int src : problem.srcs) fingerprint += " " + workspace.views[src].name;
    char range[64];
    std::snprintf(range, sizeof(range), " depth %.9g %.9g\n", problem.depth_min, problem.depth_max);
    fingerprint += range;
  }
  return fingerprint;
}

}  // namespace msp

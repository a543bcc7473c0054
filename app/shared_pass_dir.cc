#include "app/shared_pass_dir.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <utility>

#include "app/stale_files.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "patch_match/pixel_state_io.h"

namespace msp {
namespace {

constexpr char kRunFile[] = "run.txt";

// The first line where `here` and `there` differ, as "line N: this run has
// `...`, that run `...`".
std::string FirstDifference(const std::string& here, const std::string& there) {
  std::istringstream a(here), b(there);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a) line_a.clear();
    if (!more_b) line_b.clear();
    if (line_a != line_b || !more_a || !more_b) {
      return "line " + std::to_string(line) + ": this run has `" + line_a + "`, that run `" +
             line_b + "`";
    }
  }
}

}  // namespace

std::string SharedPassDirPath(const std::string& stereo_dir) {
  return JoinPaths(stereo_dir, "msp_shared");
}

SharedPassDir::SharedPassDir(std::string dir, std::vector<std::string> image_names,
                             const std::string& fingerprint)
    : dir_(std::move(dir)), image_names_(std::move(image_names)) {
  const std::string run_file = JoinPaths(dir_, kRunFile);
  // The first process of the run writes it; two that race both write theirs
  // and each reads back the one that stayed.
  if (!IsFile(run_file)) WriteFileAtomic(run_file, fingerprint);
  const std::string recorded = ReadFileToString(run_file);
  if (recorded != fingerprint) {
    throw InputError(dir_ +
                     " holds the pass states of a sharded run with other options or "
                     "problems (" +
                     run_file + " " + FirstDifference(fingerprint, recorded) +
                     "): finish that run with its options, or delete " + dir_ +
                     " to start this one over");
  }
}

std::string SharedPassDir::StatePath(int pass, int view) const {
  char pass_dir[32];
  std::snprintf(pass_dir, sizeof(pass_dir), "pass_%02d", pass);
  return JoinPaths(JoinPaths(dir_, pass_dir), image_names_.at(view) + ".state");
}

void SharedPassDir::Save(int pass, int view, const PixelState& state) {
  WriteFileAtomic(StatePath(pass, view), SerializePixelState(state));
}

bool SharedPassDir::Has(int pass, int view) { return IsFile(StatePath(pass, view)); }

PixelState SharedPassDir::Load(int pass, int view) {
  const std::string path = StatePath(pass, view);
  PixelState state;
  if (!DeserializePixelState(ReadFileToString(path), &state)) {
    throw InputError("corrupt pass state " + path +
                     " (not a whole state of this program); "
                     "delete " +
                     dir_ + " and run every shard again");
  }
  return state;
}

void SharedPassDir::Remove(int pass, int view) {
  const std::string path = StatePath(pass, view);
  std::remove(path.c_str());
  // The pass folder goes with its last state; a folder still in use stays.
  ::rmdir(std::filesystem::path(path).parent_path().c_str());
}

void SharedPassDir::Clear() {
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
  // Every map of the run is written, so no process of it writes any more:
  // temporary files in stereo/ are what killed shards left (a shard does not
  // remove them at its start, while the others write beside it).
  RemoveStaleFiles(std::filesystem::path(dir_).parent_path().string(), "");
}

}  // namespace msp

#include "patch_match/shared_passes.h"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>

#include "base/log.h"
#include "base/seconds_since.h"
#include "base/stop_request.h"

namespace msp {
namespace {

// Polling of a barrier: the first look comes soon (the processes of a run
// usually finish a pass close together), later ones every few seconds, which
// costs a shared file system nothing next to a pass of minutes.
constexpr double kFirstPollSeconds = 0.05;
constexpr double kMaxPollSeconds = 2.0;
// Images named in a timeout message; the rest are counted.
constexpr size_t kMaxNamedImages = 10;

}  // namespace

SharedPasses::SharedPasses(const SharedRun& run, const std::vector<View>& views,
                           const std::vector<Problem>& problems)
    : run_(run), views_(views), problems_(problems) {
  if (run_.exchange == nullptr) throw std::logic_error("SharedPasses: no exchange");
  for (size_t k = 0; k < problems_.size(); ++k) {
    problem_of_view_[problems_[k].ref] = static_cast<int>(k);
  }
}

int SharedPasses::LastSavedPass(int num_passes) {
  for (int pass = num_passes - 1; pass >= 0; --pass) {
    bool all = true;
    for (int k : run_.owned) all = all && run_.exchange->Has(pass, problems_[k].ref);
    if (all && !run_.owned.empty()) return pass;
  }
  return -1;
}

std::vector<int> SharedPasses::Missing(int pass) const {
  std::vector<int> missing;
  for (size_t k = 0; k < problems_.size(); ++k) {
    if (!run_.exchange->Has(pass, problems_[k].ref)) missing.push_back(static_cast<int>(k));
  }
  return missing;
}

std::string SharedPasses::DescribeMissing(const std::vector<int>& missing) const {
  std::string text;
  for (size_t i = 0; i < missing.size() && i < kMaxNamedImages; ++i) {
    const int k = missing[i];
    text += (i == 0 ? "" : ", ") + views_[problems_[k].ref].name;
    if (run_.shard.count > 0) {
      text += " (shard " + std::to_string(ShardOfProblem(k, run_.shard)) + "/" +
              std::to_string(run_.shard.count) + ")";
    }
  }
  if (missing.size() > kMaxNamedImages) {
    text += " and " + std::to_string(missing.size() - kMaxNamedImages) + " more";
  }
  return text;
}

void SharedPasses::WaitForPass(int pass, const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  double sleep_seconds = kFirstPollSeconds;
  std::vector<int> missing = Missing(pass);
  if (!missing.empty()) {
    Logf(kLogProgress, "%s: waiting for %zu image(s) of other processes to finish %s\n",
         run_.name.c_str(), missing.size(), label.c_str());
  }
  while (!missing.empty()) {
    ThrowIfStopRequested();
    const double waited = SecondsSince(start);
    if (waited >= run_.timeout_seconds) {
      throw std::runtime_error(
          run_.name + ": waited " + std::to_string(static_cast<long>(waited)) +
          " s (--MspStereo.shard_timeout) for " + std::to_string(missing.size()) +
          " image(s) to finish " + label + " in " + run_.exchange->Where() + ": " +
          DescribeMissing(missing) +
          "; start the processes that compute them (the same command with their shard or image "
          "list), then run this one again to resume");
    }
    std::this_thread::sleep_for(
        std::chrono::duration<double>(std::min(sleep_seconds, run_.timeout_seconds - waited)));
    sleep_seconds = std::min(2 * sleep_seconds, kMaxPollSeconds);
    missing = Missing(pass);
    if (missing.empty()) {
      Logf(kLogProgress, "%s: every image has finished %s (waited %.1f s)\n", run_.name.c_str(),
           label.c_str(), SecondsSince(start));
    }
  }
  if (pass > 0) {
    for (int k : run_.owned) run_.exchange->Remove(pass - 1, problems_[k].ref);
  }
}

void SharedPasses::AddSourceDepths(int pass, const std::vector<int>& sources,
                                   std::map<int, DenseMap>* depths) {
  for (int v : sources) {
    if (!problem_of_view_.count(v) || depths->count(v)) continue;
    PixelState state = run_.exchange->Load(pass, v);
    DenseMap depth(state.width, state.height, 1);
    depth.data = std::move(state.depth);
    depths->emplace(v, std::move(depth));
  }
}

}  // namespace msp

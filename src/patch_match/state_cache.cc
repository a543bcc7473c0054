#include "patch_match/state_cache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

#include "patch_match/pixel_state_io.h"

namespace msp {
namespace {

PixelState ReadSpillFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  PixelState state;
  if (!DeserializePixelState(bytes, &state)) {
    throw std::runtime_error("cannot read spilled state " + path);
  }
  return state;
}

std::vector<float> DepthOf(const PixelState& state, bool previous) {
  if (previous && state.previous_depth.empty()) {
    throw std::logic_error("StateCache: no previous depth");
  }
  return previous ? state.previous_depth : state.depth;
}

}  // namespace

StateCache::StateCache(size_t budget_bytes, std::string scratch_dir)
    : budget_bytes_(budget_bytes), scratch_dir_(std::move(scratch_dir)) {}

StateCache::~StateCache() {
  for (const auto& entry : spilled_) std::remove(entry.second.c_str());
}

bool StateCache::Contains(int id) const { return resident_.count(id) || spilled_.count(id); }

std::string StateCache::SpillPath(int id) const {
  return scratch_dir_ + "/state-" + std::to_string(getpid()) + "-" + std::to_string(id) + ".bin";
}

void StateCache::Touch(int id) {
  lru_.remove(id);
  lru_.push_front(id);
}

PixelState& StateCache::Get(int id) {
  auto it = resident_.find(id);
  if (it == resident_.end()) {
    auto sp = spilled_.find(id);
    if (sp == spilled_.end()) throw std::logic_error("StateCache: unknown image state");
    PixelState state = ReadSpillFile(sp->second);
    std::remove(sp->second.c_str());
    spilled_.erase(sp);
    resident_bytes_ += state.Bytes();
    it = resident_.emplace(id, std::move(state)).first;
  }
  Touch(id);
  return it->second;
}

std::vector<float> StateCache::ReadDepth(int id, bool previous) const {
  auto it = resident_.find(id);
  if (it != resident_.end()) return DepthOf(it->second, previous);
  auto sp = spilled_.find(id);
  if (sp == spilled_.end()) throw std::logic_error("StateCache: unknown image state");
  // Read, not taken back: the file stays, so nothing is written again.
  return DepthOf(ReadSpillFile(sp->second), previous);
}

PixelState StateCache::Take(int id) {
  PixelState state = std::move(Get(id));
  auto it = resident_.find(id);
  resident_bytes_ -= state.Bytes();
  resident_.erase(it);
  lru_.remove(id);
  return state;
}

void StateCache::Put(int id, PixelState state) {
  auto sp = spilled_.find(id);
  if (sp != spilled_.end()) {
    std::remove(sp->second.c_str());
    spilled_.erase(sp);
  }
  auto it = resident_.find(id);
  if (it != resident_.end()) {
    resident_bytes_ -= it->second.Bytes();
    resident_.erase(it);
  }
  resident_bytes_ += state.Bytes();
  resident_.emplace(id, std::move(state));
  Touch(id);
}

void StateCache::Spill(int id) {
  auto it = resident_.find(id);
  if (it == resident_.end()) return;
  mkdir(scratch_dir_.c_str(), 0755);
  const std::string path = SpillPath(id);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << SerializePixelState(it->second);
  if (!out) throw std::runtime_error("cannot spill state to " + path + " (disk full?)");
  resident_bytes_ -= it->second.Bytes();
  resident_.erase(it);
  spilled_[id] = path;
  lru_.remove(id);
  ++num_spills_;
}

void StateCache::EnforceBudget(int keep) {
  while (resident_bytes_ > budget_bytes_) {
    int victim = -1;
    for (auto it = lru_.rbegin(); it != lru_.rend(); ++it) {
      if (*it != keep) {
        victim = *it;
        break;
      }
    }
    if (victim < 0) return;  // only `keep` is resident: it must stay
    Spill(victim);
  }
}

}  // namespace msp

// Per-image PatchMatch state kept between passes within a memory budget
// (--PatchMatchStereo.cache_size); the least recently used states beyond it
// are spilled to files in the scratch folder and read back when needed.
#pragma once

#include <cstddef>
#include <list>
#include <map>
#include <string>
#include <vector>

#include "engine/pixel_state.h"

namespace msp {

class StateCache {
 public:
  StateCache(size_t budget_bytes, std::string scratch_dir);
  ~StateCache();
  StateCache(const StateCache&) = delete;
  StateCache& operator=(const StateCache&) = delete;

  bool Contains(int id) const;
  // The state of image `id`, read back from the scratch folder if it was spilled.
  PixelState& Get(int id);
  // Removes the state of image `id` from the cache and returns it.
  PixelState Take(int id);
  // A copy of the depth of image `id` (its previous_depth when `previous`,
  // which must be there), from memory or read from its spilled file, which
  // stays: the state is not made resident.
  std::vector<float> ReadDepth(int id, bool previous) const;
  void Put(int id, PixelState state);
  // Spills other states until the resident ones fit the budget; `keep` stays.
  void EnforceBudget(int keep);

  size_t ResidentBytes() const { return resident_bytes_; }
  int NumSpills() const { return num_spills_; }

 private:
  std::string SpillPath(int id) const;
  void Spill(int id);
  void Touch(int id);

  size_t budget_bytes_;
  std::string scratch_dir_;
  std::map<int, PixelState> resident_;
  std::map<int, std::string> spilled_;
  std::list<int> lru_;  // front = most recently used
  size_t resident_bytes_ = 0;
  int num_spills_ = 0;
};

}  // namespace msp

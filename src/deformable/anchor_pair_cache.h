// The anchor windows' costs that neighbouring deformable updates share.
// Candidate k of a deformable update is anchor k's plane continued to the
// pixel (core/deformable/deformable_update.h), so the cost of anchor window a under it
// in a source view depends on the two anchors alone, not on the pixel. The
// pixels of a textureless region share most of their anchors, so most
// (candidate, window) pairs recur from pixel to pixel. Each pair is warped with the plane as anchor k's own
// pixel sees it, so its cost is the same whichever pixel asks first, whatever
// the cache holds and whatever the thread count.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/deformable/anchor_windows.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/deformable_update.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {

// A direct-mapped cache of pair costs in every source view: a pair's slot is
// a hash of its two pixels, and a new pair evicts the one that held it. A
// row of a sweep revisits the anchors of the rows before, so a cache of a few
// MiB serves most of the pairs the next pixels ask for.
class AnchorPairCache {
 public:
  explicit AnchorPairCache(int num_views);

  // Forgets every pair: the planes they were warped with changed.
  void Clear();

  // The pair of the window of pixel `window_pixel` under the plane of pixel
  // `plane_pixel` (pixel indices).
  static uint64_t Key(int plane_pixel, int window_pixel);

  // Starts fetching the pair's slot from memory, ahead of Find or Store.
  void Prefetch(uint64_t key) const { __builtin_prefetch(SlotOf(key)); }

  // The pair's costs in every view, or nullptr when the cache does not hold them.
  const float* Find(uint64_t key) const;

  // Room for the pair's costs, evicting the pair that held the slot.
  float* Store(uint64_t key);

 private:
  // A slot is one 64-byte line (more with over 14 views): the key, then the costs.
  uint64_t* SlotOf(uint64_t key) const;

  size_t slot_words_;  // 64-bit words per slot
  // Mapped, not allocated: a block of megabytes from malloc raises glibc's
  // mmap threshold, after which the passes' smaller buffers fragment the
  // heap and raise the peak memory.
  struct Unmap {
    size_t bytes;
    void operator()(uint64_t* p) const;
  };
  using Slots = std::unique_ptr<uint64_t[], Unmap>;
  static Slots MapSlots(size_t bytes);
  Slots slots_;
};

// Caches lent to the rows of a sweep, one per row being swept at a time.
class AnchorPairCachePool {
 public:
  explicit AnchorPairCachePool(int num_views) : num_views_(num_views) {}

  int num_views() const { return num_views_; }

  // A cache to use until Release, with whatever pairs it holds.
  AnchorPairCache* Acquire();
  void Release(AnchorPairCache* cache);

  // Clears every cache; no cache may be lent out.
  void ClearAll();

 private:
  int num_views_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<AnchorPairCache>> all_;
  std::vector<AnchorPairCache*> idle_;
};

// The anchor sums of a deformable update's anchors' candidates
// (core::DirectAnchorSums' role) from the pairs of `cache`, computing and
// adding the pairs it lacks. Only for core::DeformableUpdatePixel, whose
// candidate k is anchor k's plane in `planes`, the iteration's snapshot: the
// sums are taken under that plane, not under `prepared`.
class CachedAnchorSums {
 public:
  CachedAnchorSums(const core::PassParams& params, const core::PlaneMapView& planes,
                   const core::DeformableParams& d, AnchorPairCache* cache)
      : params_(params), planes_(planes), d_(d), cache_(cache) {}

  void operator()(const core::AnchorWindows& w, const core::PreparedPlane* prepared,
                  const uint32_t* need, core::CandidateAnchorSums* out) const;

 private:
  const core::PassParams& params_;
  const core::PlaneMapView& planes_;
  core::DeformableParams d_;
  AnchorPairCache* cache_;
};

}  // namespace msp

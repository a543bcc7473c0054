#include "deformable/anchor_pair_cache.h"

#include <sys/mman.h>

#include <algorithm>
#include <new>

#include "core/deformable/deformable_sweep_pixel.h"

namespace msp {
namespace {

// 2^16 slots of 64 bytes: 4 MiB with up to 14 source views.
constexpr int kLog2Slots = 16;
constexpr size_t kNumSlots = size_t{1} << kLog2Slots;
constexpr size_t kLineWords = 8;
constexpr uint64_t kEmpty = ~0ull;

int PixelOf(const core::PassParams& p, int col, int row) { return row * p.state.width + col; }

}  // namespace

void AnchorPairCache::Unmap::operator()(uint64_t* p) const { munmap(p, bytes); }

AnchorPairCache::Slots AnchorPairCache::MapSlots(size_t bytes) {
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  return Slots(static_cast<uint64_t*>(p), Unmap{bytes});  // page-aligned: slots start cache lines
}

AnchorPairCache::AnchorPairCache(int num_views)
    // The key's word, then the costs (2 per word), in whole cache lines.
    : slot_words_((1 + (num_views + 1) / 2 + kLineWords - 1) / kLineWords * kLineWords),
      slots_(MapSlots(kNumSlots * slot_words_ * sizeof(uint64_t))) {
  Clear();
}

void AnchorPairCache::Clear() {
  for (size_t slot = 0; slot < kNumSlots; ++slot) slots_[slot * slot_words_] = kEmpty;
}

uint64_t AnchorPairCache::Key(int plane_pixel, int window_pixel) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(plane_pixel)) << 32) |
         static_cast<uint32_t>(window_pixel);
}

uint64_t* AnchorPairCache::SlotOf(uint64_t key) const {
  const size_t slot = static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> (64 - kLog2Slots));
  return slots_.get() + slot * slot_words_;
}

const float* AnchorPairCache::Find(uint64_t key) const {
  const uint64_t* slot = SlotOf(key);
  return slot[0] == key ? reinterpret_cast<const float*>(slot + 1) : nullptr;
}

float* AnchorPairCache::Store(uint64_t key) {
  uint64_t* slot = SlotOf(key);
  slot[0] = key;
  return reinterpret_cast<float*>(slot + 1);
}

AnchorPairCache* AnchorPairCachePool::Acquire() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (idle_.empty()) {
    all_.push_back(std::make_unique<AnchorPairCache>(num_views_));
    return all_.back().get();
  }
  AnchorPairCache* cache = idle_.back();
  idle_.pop_back();
  return cache;
}

void AnchorPairCachePool::Release(AnchorPairCache* cache) {
  std::lock_guard<std::mutex> lock(mutex_);
  idle_.push_back(cache);
}

void AnchorPairCachePool::ClearAll() {
  for (auto& cache : all_) cache->Clear();
}

void CachedAnchorSums::operator()(const core::AnchorWindows& w, const core::PreparedPlane* prepared,
                                  const uint32_t* need, core::CandidateAnchorSums* out) const {
  const core::PassParams& p = params_;
  const core::NccParams anchor_ncc = core::AnchorNccParams(p.ncc, d_);
  const int n = w.count;
  constexpr int kViews = core::kMaxSourceViews;  // the stride of pair[k][a]
  // The costs of every pair this update needs: pair[k][a][j].
  float pair[core::kMaxAnchors][core::kMaxAnchors][core::kMaxSourceViews];
  core::PlaneWarp warp[core::kMaxAnchors];
  bool cached[core::kMaxAnchors] = {};
  int missing_k[core::kMaxAnchors * core::kMaxAnchors];
  int missing_a[core::kMaxAnchors * core::kMaxAnchors];
  int num_missing = 0;
  uint64_t key[core::kMaxAnchors][core::kMaxAnchors];
  for (int k = 0; k < n; ++k) {
    if (need[k] == 0u) continue;
    for (int a = 0; a < n; ++a) {
      key[k][a] =
          AnchorPairCache::Key(PixelOf(p, w.col[k], w.row[k]), PixelOf(p, w.col[a], w.row[a]));
      cache_->Prefetch(key[k][a]);
    }
  }
  for (int k = 0; k < n; ++k) {
    if (need[k] == 0u) continue;
    // Anchor k's plane as its own pixel sees it: the same for every pixel.
    const core::PreparedPlane own = core::AnchorOwnPlane(p, planes_, w, k);
    if (!own.valid) {
      // Behind the camera at the anchor, in front at the pixel: only float
      // rounding of a plane through the camera centre gets here. Scored on
      // the spot, as DirectAnchorSums would.
      core::DirectAnchorSums{p, d_}.ForCandidate(w, prepared[k], need[k], out->sum[k]);
      continue;
    }
    cached[k] = true;
    warp[k] = own.warp;
    for (int a = 0; a < n; ++a) {
      const float* costs = cache_->Find(key[k][a]);
      if (costs != nullptr) {
        std::copy(costs, costs + p.num_src, pair[k][a]);
      } else {
        missing_k[num_missing] = k;
        missing_a[num_missing] = a;
        ++num_missing;
      }
    }
  }
  // The missing pairs, a vector lane each, every view.
  for (int first = 0; first < num_missing; first += core::kWindowLanes) {
    const int lanes = std::min(core::kWindowLanes, num_missing - first);
    core::PlaneWarp lane_warp[core::kWindowLanes];
    for (int l = 0; l < lanes; ++l) lane_warp[l] = warp[missing_k[first + l]];
    core::AnchorPairLanes batch;
    core::PrepareAnchorPairLanes(w, missing_a + first, lane_warp, lanes, &batch);
    for (int j = 0; j < p.num_src; ++j) {
      float costs[core::kWindowLanes];
      core::AnchorPairCosts(w, batch, p.src[j].rel, p.ref_image, p.src[j].image, anchor_ncc, costs);
      for (int l = 0; l < lanes; ++l)
        pair[missing_k[first + l]][missing_a[first + l]][j] = costs[l];
    }
    for (int l = 0; l < lanes; ++l) {
      const int k = missing_k[first + l], a = missing_a[first + l];
      std::copy(pair[k][a], pair[k][a] + p.num_src, cache_->Store(key[k][a]));
    }
  }
  for (int k = 0; k < n; ++k) {
    if (!cached[k]) continue;
    for (int j = 0; j < p.num_src; ++j) {
      if ((need[k] >> j) & 1u) out->sum[k][j] = core::SumPairCosts(&pair[k][0][j], n, kViews);
    }
  }
}

}  // namespace msp

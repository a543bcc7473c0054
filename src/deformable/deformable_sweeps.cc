#include "deformable/deformable_sweeps.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "base/nearest_marked_pixels.h"
#include "base/parallel_for.h"
#include "base/seconds_since.h"
#include "core/deformable/deformable_sweep_pixel.h"
#include "core/deformable/deformable_update.h"
#include "core/deformable/refine_and_classify.h"
#include "deformable/anchor_pair_cache.h"

namespace msp {
namespace {

static_assert(core::kMaxAnchors <= core::kMaxPriorAnchors,
              "every anchor of a pixel fits the prior's anchor subsets");

// Pixel p's anchors as the segmentation prior reads them: APD's anchors (the
// first kMaxAnchors), also when disassemble-clustering keeps more.
core::PriorAnchors ToPriorAnchors(const core::Camera& cam, const core::AnchorSet& set,
                                  const float* depth, int width, int col, int row) {
  core::PriorAnchors out;
  out.col = col;
  out.row = row;
  out.count = set.count < core::kMaxAnchors ? set.count : core::kMaxAnchors;
  for (int k = 0; k < out.count; ++k) {
    out.cols[k] = set.cols[k];
    out.rows[k] = set.rows[k];
    out.points[k] =
        core::BackProject(cam, static_cast<float>(set.cols[k]), static_cast<float>(set.rows[k]),
                          depth[set.rows[k] * width + set.cols[k]]);
  }
  return out;
}

// The class `classify(col, row)` of every pixel, rows in parallel.
template <typename ClassifyFn>
std::vector<uint8_t> PixelClasses(const core::PassParams& params, int num_threads,
                                  ClassifyFn classify) {
  const int width = params.state.width;
  std::vector<uint8_t> classes(static_cast<size_t>(width) * params.state.height);
  ParallelFor(0, params.state.height, num_threads, [&](int row) {
    for (int col = 0; col < width; ++col) {
      classes[static_cast<size_t>(row) * width + col] = classify(col, row);
    }
  });
  return classes;
}

}  // namespace

std::vector<uint8_t> ClassifyPixels(const core::PassParams& params,
                                    const core::ReliabilityParams& rp, int num_threads) {
  return PixelClasses(params, num_threads,
                      [&](int col, int row) { return core::ClassifyPixel(params, col, row, rp); });
}

ReliabilityMaps ClassifyState(const core::PassParams& params, const core::ReliabilityParams& rp,
                              int num_threads) {
  return MakeReliabilityMaps(ClassifyPixels(params, rp, num_threads), params.state.width,
                             params.state.height, num_threads);
}

std::vector<uint8_t> LocalRefineAndClassifyState(const core::PassParams& params,
                                                 const core::ReliabilityParams& rp,
                                                 int num_threads) {
  return PixelClasses(params, num_threads, [&](int col, int row) {
    return core::LocalRefineAndClassifyPixel(params, col, row, rp);
  });
}

ReliabilityMaps MakeReliabilityMaps(std::vector<uint8_t> classes, int width, int height,
                                    int num_threads) {
  if (classes.size() != static_cast<size_t>(width) * height) {
    throw std::logic_error("reliability classes and pixel state differ in size");
  }
  ReliabilityMaps maps;
  maps.width = width;
  maps.height = height;
  maps.classes = std::move(classes);
  for (uint8_t c : maps.classes) {
    maps.num_reliable += c == core::kReliable;
    maps.num_unreliable += c == core::kUnreliable;
  }
  maps.nearest = NearestReliablePixels(maps.classes.data(), width, height, num_threads);
  return maps;
}

int AssignAnchorSlots(const std::vector<uint8_t>& classes, std::vector<int>* slot) {
  slot->assign(classes.size(), -1);
  int num_slots = 0;
  for (size_t i = 0; i < classes.size(); ++i) {
    if (classes[i] == core::kUnreliable) (*slot)[i] = num_slots++;
  }
  return num_slots;
}

void CollectPriorAnchors(const core::Camera& cam, const std::vector<int>& slot,
                         const std::vector<core::AnchorSet>& anchors, const float* depth, int width,
                         int height, int num_threads, std::vector<int>* row_start,
                         std::vector<core::PriorAnchors>* out) {
  auto anchored = [&](int i) { return slot[i] >= 0 && anchors[slot[i]].count > 0; };
  row_start->assign(height + 1, 0);
  ParallelFor(0, height, num_threads, [&](int row) {
    int count = 0;
    for (int col = 0; col < width; ++col) count += anchored(row * width + col);
    (*row_start)[row + 1] = count;
  });
  for (int row = 0; row < height; ++row) (*row_start)[row + 1] += (*row_start)[row];
  out->resize((*row_start)[height]);
  ParallelFor(0, height, num_threads, [&](int row) {
    int entry = (*row_start)[row];
    for (int col = 0; col < width; ++col) {
      const int i = row * width + col;
      if (anchored(i))
        (*out)[entry++] = ToPriorAnchors(cam, anchors[slot[i]], depth, width, col, row);
    }
  });
}

DeformableStats RunDeformableCheckerboardIterations(
    const core::PassParams& params, const ReliabilityMaps& maps, const DeformableSettings& settings,
    int num_iterations, int num_threads, DeformableBuffers* buffers,
    std::vector<core::PriorAnchors>* prior_anchors) {
  const core::PixelStateView& s = params.state;
  const int width = s.width, height = s.height;
  const size_t n = static_cast<size_t>(width) * height;
  // Slots of the unreliable pixels in the anchor array.
  std::vector<int>& slot = buffers->slot;
  const int num_slots = AssignAnchorSlots(maps.classes, &slot);
  std::vector<core::AnchorSet>& anchors = buffers->anchors;
  std::vector<core::AnchorHits>& hits = buffers->hits;
  anchors.resize(num_slots);
  hits.resize(num_slots);
  std::vector<uint32_t>& solutions = buffers->solutions;
  if (settings.synergistic) solutions.resize(num_slots);
  std::vector<float>& depth = buffers->depth;
  std::vector<float>& normal = buffers->normal;
  depth.resize(n);  // sized before the views below take their addresses
  normal.resize(3 * n);
  const core::PlaneMapView planes{depth.data(), normal.data(), width, height};
  const core::AnchorMaps anchor_maps{
      maps.classes.data(), maps.nearest.data(),  depth.data(), width, height,
      settings.edges,      settings.nearest_edge};
  if (buffers->caches == nullptr || buffers->caches->num_views() != params.num_src) {
    buffers->caches = std::make_unique<AnchorPairCachePool>(params.num_src);
  }
  AnchorPairCachePool& caches = *buffers->caches;
  DeformableStats stats;
  for (int iteration = 0; iteration < num_iterations; ++iteration) {
    caches.ClearAll();
    std::copy(s.depth, s.depth + n, depth.begin());
    std::copy(s.normal, s.normal + 3 * n, normal.begin());
    std::atomic<long long> anchored{0};
    const auto anchors_start = std::chrono::steady_clock::now();
    ParallelFor(0, height, num_threads, [&](int row) {
      int count = 0;
      for (int col = 0; col < width; ++col) {
        const int k = slot[row * width + col];
        if (k < 0) continue;
        count += core::FindPixelAnchors(params, anchor_maps, settings.anchors, col, row, iteration,
                                        &hits[k], &anchors[k],
                                        settings.synergistic ? &solutions[k] : nullptr);
      }
      anchored += count;
    });
    stats.anchored_updates += anchored;
    stats.anchor_seconds += SecondsSince(anchors_start);
    if (iteration == 0 && prior_anchors != nullptr) {
      CollectPriorAnchors(params.ref_camera, slot, anchors, depth.data(), width, height,
                          num_threads, &buffers->row_start, prior_anchors);
    }
    const auto sweep_start = std::chrono::steady_clock::now();
    for (int color = 0; color < 2; ++color) {
      // Tasks of a few rows each: a cache then serves consecutive rows, whose
      // pixels share most of their anchors.
      constexpr int kRowsPerTask = 8;
      ParallelFor(0, (height + kRowsPerTask - 1) / kRowsPerTask, num_threads, [&](int task) {
        const int end = std::min(height, (task + 1) * kRowsPerTask);
        core::PixelSampling sampling;
        sampling.optimize = iteration < settings.synergy_iterations;
        sampling.params = settings.synergy;
        auto rows = [&](const auto& anchor_sums) {
          for (int row = task * kRowsPerTask; row < end; ++row) {
            for (int col = (row + color) & 1; col < width; col += 2) {
              const int k = slot[row * width + col];
              sampling.solution = k >= 0 && settings.synergistic ? &solutions[k] : nullptr;
              core::DeformableSweepPixel(params, col, row, iteration,
                                         k >= 0 ? &anchors[k] : nullptr, planes, settings.cost,
                                         anchor_sums, sampling);
            }
          }
        };
        if (!core::SharesAnchorPairs(settings.cost, settings.synergistic)) {
          rows(core::DirectAnchorSums{params, settings.cost});
          return;
        }
        AnchorPairCache* cache = caches.Acquire();
        rows(CachedAnchorSums(params, planes, settings.cost, cache));
        caches.Release(cache);
      });
    }
    stats.sweep_seconds += SecondsSince(sweep_start);
  }
  return stats;
}

}  // namespace msp

#include "prior/segmentation_prior.h"

#include <algorithm>
#include <cassert>
#include <unordered_map>

#include "base/parallel_for.h"
#include "core/math/rng.h"

namespace msp {
namespace {

// Stream index of the best-layer RANSAC in the (seed, image, pass, iteration,
// pixel) key, far from the sweep iterations so the streams never coincide.
constexpr uint32_t kBestLayerStream = 0x5E6A0001u;
// Unreliable pixels handed to one worker at a time.
constexpr int kPixelsPerTask = 256;

// Maps arbitrary label ids of one level to dense region indices 0..K-1 in
// raster order of first appearance.
std::vector<int> CompactRegions(const std::vector<int32_t>& labels, int* num_regions) {
  std::unordered_map<int32_t, int> index;
  std::vector<int> regions(labels.size());
  int32_t last_label = 0;
  int last_region = -1;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (last_region < 0 || labels[i] != last_label) {
      last_label = labels[i];
      last_region = index.emplace(last_label, static_cast<int>(index.size())).first->second;
    }
    regions[i] = last_region;
  }
  *num_regions = static_cast<int>(index.size());
  return regions;
}

}  // namespace

std::vector<uint8_t> ComputeBoundaryMap(const std::vector<int32_t>& labels, int width, int height) {
  assert(labels.size() == static_cast<size_t>(width) * height);
  std::vector<uint8_t> boundary(labels.size(), 0);
  for (int row = 0; row < height; ++row) {
    const size_t base = static_cast<size_t>(row) * width;
    for (int col = 0; col < width; ++col) {
      const size_t i = base + col;
      // Mark both pixels of every differing 4-neighbour pair (right, down).
      if (col + 1 < width && labels[i] != labels[i + 1]) boundary[i] = boundary[i + 1] = 1;
      if (row + 1 < height && labels[i] != labels[i + width]) {
        boundary[i] = boundary[i + width] = 1;
      }
    }
  }
  return boundary;
}

std::vector<std::vector<uint8_t>> ComputeBoundaryMaps(const LabelLayers& layers) {
  std::vector<std::vector<uint8_t>> boundaries;
  boundaries.reserve(layers.levels.size());
  for (const std::vector<int32_t>& level : layers.levels) {
    boundaries.push_back(ComputeBoundaryMap(level, layers.width, layers.height));
  }
  return boundaries;
}

std::vector<uint8_t> UnionBoundaryMap(const std::vector<std::vector<uint8_t>>& boundaries) {
  if (boundaries.empty()) return {};
  std::vector<uint8_t> result = boundaries[0];
  for (size_t n = 1; n < boundaries.size(); ++n) {
    assert(boundaries[n].size() == result.size());
    for (size_t i = 0; i < result.size(); ++i) result[i] |= boundaries[n][i];
  }
  return result;
}

core::BoundaryView MakeBoundaryView(const std::vector<uint8_t>& boundary, int width, int height) {
  assert(boundary.size() == static_cast<size_t>(width) * height);
  return core::BoundaryView{boundary.data(), width, height, width};
}

// S_max of every anchored pixel (eq. 4), the layers tested in one walk per anchor.
std::vector<uint32_t> ChooseBestLayers(const LabelLayers& layers,
                                       const std::vector<std::vector<uint8_t>>& boundaries,
                                       const std::vector<core::PriorAnchors>& pixels,
                                       const BestLayerOptions& options) {
  const int num_layers = layers.NumLevels();
  assert(num_layers <= core::kMaxLabelLayers);
  assert(static_cast<int>(boundaries.size()) == num_layers);
  // Bit n of a pixel = the pixel is on B_n: one walk per anchor tests all layers.
  std::vector<uint32_t> packed(static_cast<size_t>(layers.width) * layers.height, 0u);
  for (int n = 0; n < num_layers; ++n) {
    for (size_t i = 0; i < packed.size(); ++i) packed[i] |= uint32_t{boundaries[n][i]} << n;
  }
  const core::LayerBoundaryView view{packed.data(), layers.width, layers.height, layers.width};
  std::vector<uint32_t> best(static_cast<size_t>(layers.width) * layers.height, 0u);
  const int num_pixels = static_cast<int>(pixels.size());
  const int num_tasks = (num_pixels + kPixelsPerTask - 1) / kPixelsPerTask;
  ParallelFor(0, num_tasks, options.num_threads, [&](int task) {
    const int end = std::min(num_pixels, (task + 1) * kPixelsPerTask);
    for (int i = task * kPixelsPerTask; i < end; ++i) {
      const core::PriorAnchors& anchors = pixels[i];
      const uint32_t pixel = static_cast<uint32_t>(anchors.row * layers.width + anchors.col);
      const core::Rng rng = core::MakeRng(
          core::RngKey(options.seed, options.image, options.pass, kBestLayerStream, pixel));
      best[pixel] = core::BestLayersForPixel(anchors, view, num_layers, options.ransac, rng);
    }
  });
  return best;
}

// Label retention (eq. 5): region k of layer n is kept when n is the layer
// most of the region's pixels chose as S_max.
std::vector<std::vector<uint8_t>> RetainRegions(const LabelLayers& layers,
                                                const std::vector<uint32_t>& best_layers) {
  const int num_layers = layers.NumLevels();
  const size_t num_pixels = static_cast<size_t>(layers.width) * layers.height;
  assert(best_layers.size() == num_pixels);
  std::vector<std::vector<uint8_t>> kept(num_layers);
  for (int n = 0; n < num_layers; ++n) {
    int num_regions = 0;
    const std::vector<int> regions = CompactRegions(layers.levels[n], &num_regions);
    // votes[k * L + l] = #{p in region k of level n : layer l is a best layer of p}.
    std::vector<int> votes(static_cast<size_t>(num_regions) * num_layers, 0);
    for (size_t i = 0; i < num_pixels; ++i) {
      if (best_layers[i] == 0u) continue;
      int* v = &votes[static_cast<size_t>(regions[i]) * num_layers];
      for (int l = 0; l < num_layers; ++l) v[l] += (best_layers[i] >> l) & 1u;
    }
    std::vector<uint8_t> region_kept(num_regions, 0);
    for (int k = 0; k < num_regions; ++k) {
      const int* v = &votes[static_cast<size_t>(k) * num_layers];
      int argmax = 0;  // first maximum: ties go to the coarser layer
      for (int l = 1; l < num_layers; ++l) {
        if (v[l] > v[argmax]) argmax = l;
      }
      region_kept[k] = argmax == n;
    }
    kept[n].resize(num_pixels);
    for (size_t i = 0; i < num_pixels; ++i) {
      kept[n][i] = layers.levels[n][i] != 0 && region_kept[regions[i]];
    }
  }
  return kept;
}

Segmentation AggregateRegions(const LabelLayers& layers,
                              const std::vector<std::vector<uint8_t>>& kept) {
  const size_t num_pixels = static_cast<size_t>(layers.width) * layers.height;
  assert(kept.size() == layers.levels.size());
  Segmentation out;
  out.width = layers.width;
  out.height = layers.height;
  out.labels.assign(num_pixels, 0);
  // Fold the levels in one at a time: the label after level n is a dense id of
  // the pair (label after level n-1, kept region id of level n or 0).
  for (int n = 0; n < layers.NumLevels(); ++n) {
    std::unordered_map<uint64_t, int32_t> ids;
    uint64_t last_key = 0;
    int32_t last_id = -1;
    for (size_t i = 0; i < num_pixels; ++i) {
      const uint32_t region = kept[n][i] ? static_cast<uint32_t>(layers.levels[n][i]) : 0u;
      const uint64_t key =
          (static_cast<uint64_t>(static_cast<uint32_t>(out.labels[i])) << 32) | region;
      if (last_id < 0 || key != last_key) {
        last_key = key;
        last_id = ids.emplace(key, static_cast<int32_t>(ids.size())).first->second;
      }
      out.labels[i] = last_id;
    }
  }
  out.edges = ComputeBoundaryMap(out.labels, out.width, out.height);
  return out;
}

Segmentation UnionOfLayers(const LabelLayers& layers) {
  std::vector<std::vector<uint8_t>> kept(layers.levels.size());
  for (size_t n = 0; n < kept.size(); ++n) {
    kept[n].resize(layers.levels[n].size());
    for (size_t i = 0; i < kept[n].size(); ++i) kept[n][i] = layers.levels[n][i] != 0;
  }
  return AggregateRegions(layers, kept);
}

}  // namespace msp

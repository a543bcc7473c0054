#include "prior/multiscale_segmentation.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace msp {
namespace {

// Gaussian pre-smoothing of Felzenszwalb-Huttenlocher: sigma 0.8 removes
// sensor noise and digitisation artefacts without moving edges.
constexpr float kSmoothingSigma = 0.8f;
// Kernel half width in sigmas.
constexpr float kKernelSigmas = 4.0f;
// Colours are compared in 0..255 units, the scale of the usual k values.
constexpr float kColorScale = 255.0f;
// Scene level (coarsest) and feature level (finest) settings at the
// reference size: k 1500 leaves a few large regions (walls, floor, objects),
// k 150 splits them into parts; min_size as a fraction of the image area.
constexpr float kSceneK = 1500.0f;
constexpr float kFeatureK = 150.0f;
constexpr double kSceneMinSizeFraction = 1.0 / 500.0;
constexpr double kFeatureMinSizeFraction = 1.0 / 10000.0;
// Image area at which k holds as given (640 x 480). k grows with larger
// areas because tau = k / |C| is measured in pixels; it does not shrink for
// smaller images, where sensor noise, not region size, would then decide.
constexpr double kReferenceArea = 640.0 * 480.0;
// No level keeps regions smaller than a 3x3 block: they are noise at any scale.
constexpr int kMinRegionFloor = 9;

// The 8-connected grid as four edge directions per pixel (right, down,
// down-right, up-right); an edge is packed as pixel << 2 | direction.
constexpr int kNumDirections = 4;
constexpr int kDirCol[kNumDirections] = {1, 0, 1, 1};
constexpr int kDirRow[kNumDirections] = {0, 1, 1, -1};

class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(n), size_(n, 1) {
    for (int i = 0; i < n; ++i) parent_[i] = i;
  }
  int Find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];  // path halving
      x = parent_[x];
    }
    return x;
  }
  // Joins two roots; returns the new root.
  int Join(int a, int b) {
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return a;
  }
  int Size(int root) const { return size_[root]; }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

// Separable Gaussian blur of the three colour planes, scaled to 0..255.
std::vector<float> SmoothColor(const DenseMap& color) {
  const int w = color.width;
  const int h = color.height;
  const int radius = static_cast<int>(std::ceil(kKernelSigmas * kSmoothingSigma));
  std::vector<float> kernel(2 * radius + 1);
  float sum = 0.0f;
  for (int i = -radius; i <= radius; ++i) {
    kernel[i + radius] = std::exp(-0.5f * i * i / (kSmoothingSigma * kSmoothingSigma));
    sum += kernel[i + radius];
  }
  for (float& v : kernel) v /= sum;
  std::vector<float> out(static_cast<size_t>(3) * w * h);
  std::vector<float> tmp(static_cast<size_t>(w) * h);
  for (int c = 0; c < 3; ++c) {
    const float* src = color.Plane(c);
    float* dst = out.data() + static_cast<size_t>(c) * w * h;
    for (int row = 0; row < h; ++row) {  // horizontal pass, clamped border
      for (int col = 0; col < w; ++col) {
        float acc = 0.0f;
        for (int i = -radius; i <= radius; ++i) {
          const int x = std::clamp(col + i, 0, w - 1);
          acc += kernel[i + radius] * src[static_cast<size_t>(row) * w + x];
        }
        tmp[static_cast<size_t>(row) * w + col] = acc;
      }
    }
    for (int row = 0; row < h; ++row) {  // vertical pass, clamped border
      for (int col = 0; col < w; ++col) {
        float acc = 0.0f;
        for (int i = -radius; i <= radius; ++i) {
          const int y = std::clamp(row + i, 0, h - 1);
          acc += kernel[i + radius] * tmp[static_cast<size_t>(y) * w + col];
        }
        dst[static_cast<size_t>(row) * w + col] = acc * kColorScale;
      }
    }
  }
  return out;
}

// The sorted edge list: weight bits (non-negative floats order like their
// bit patterns) in the high word, the packed edge in the low word, so one
// integer sort orders by weight with a deterministic tie-break.
std::vector<uint64_t> SortedEdges(const std::vector<float>& rgb, int w, int h) {
  const size_t plane = static_cast<size_t>(w) * h;
  assert(plane < (size_t{1} << 30));  // the packed edge holds a 30-bit pixel index
  std::vector<uint64_t> edges;
  edges.reserve(plane * kNumDirections);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const size_t p = static_cast<size_t>(row) * w + col;
      for (int d = 0; d < kNumDirections; ++d) {
        const int c2 = col + kDirCol[d];
        const int r2 = row + kDirRow[d];
        if (c2 >= w || r2 < 0 || r2 >= h) continue;
        const size_t q = static_cast<size_t>(r2) * w + c2;
        float dist2 = 0.0f;
        for (int c = 0; c < 3; ++c) {
          const float diff = rgb[c * plane + p] - rgb[c * plane + q];
          dist2 += diff * diff;
        }
        const float weight = std::sqrt(dist2);
        uint32_t bits;
        std::memcpy(&bits, &weight, sizeof(bits));
        edges.push_back((static_cast<uint64_t>(bits) << 32) | (p << 2) | d);
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

void EdgeEnds(uint64_t edge, int w, int* a, int* b) {
  const uint32_t packed = static_cast<uint32_t>(edge);
  const int p = static_cast<int>(packed >> 2);
  const int d = static_cast<int>(packed & 3u);
  *a = p;
  *b = p + kDirRow[d] * w + kDirCol[d];
}

float EdgeWeight(uint64_t edge) {
  const uint32_t bits = static_cast<uint32_t>(edge >> 32);
  float weight;
  std::memcpy(&weight, &bits, sizeof(weight));
  return weight;
}

std::vector<int32_t> SegmentSortedEdges(const std::vector<uint64_t>& edges, int w, int h,
                                        const GraphSegmentationScale& scale) {
  const int n = w * h;
  DisjointSets sets(n);
  // threshold[root] = Int(C) + k / |C|, the largest edge weight C accepts.
  std::vector<float> threshold(n, scale.k);
  for (uint64_t edge : edges) {
    int a, b;
    EdgeEnds(edge, w, &a, &b);
    a = sets.Find(a);
    b = sets.Find(b);
    if (a == b) continue;
    const float weight = EdgeWeight(edge);
    if (weight <= threshold[a] && weight <= threshold[b]) {
      const int root = sets.Join(a, b);
      threshold[root] = weight + scale.k / sets.Size(root);
    }
  }
  for (uint64_t edge : edges) {  // merge regions below min_size, cheapest edges first
    int a, b;
    EdgeEnds(edge, w, &a, &b);
    a = sets.Find(a);
    b = sets.Find(b);
    if (a != b && (sets.Size(a) < scale.min_size || sets.Size(b) < scale.min_size)) {
      sets.Join(a, b);
    }
  }
  std::vector<int32_t> labels(n);
  std::unordered_map<int, int32_t> ids;
  for (int i = 0; i < n; ++i) {
    labels[i] = ids.emplace(sets.Find(i), static_cast<int32_t>(ids.size()) + 1).first->second;
  }
  return labels;
}

}  // namespace

GraphSegmentationScale SegmentationScale(int level, int num_levels, int width, int height) {
  const double fraction = num_levels > 1 ? static_cast<double>(level) / (num_levels - 1) : 0.0;
  const double area = static_cast<double>(width) * height;
  const double area_factor = std::max(1.0, area / kReferenceArea);
  GraphSegmentationScale scale;
  scale.k = static_cast<float>(kSceneK * std::pow(kFeatureK / kSceneK, fraction) * area_factor);
  const double min_fraction =
      kSceneMinSizeFraction * std::pow(kFeatureMinSizeFraction / kSceneMinSizeFraction, fraction);
  scale.min_size = std::max(kMinRegionFloor, static_cast<int>(std::lround(min_fraction * area)));
  return scale;
}

std::vector<int32_t> SegmentGraph(const DenseMap& color, const GraphSegmentationScale& scale) {
  assert(color.channels == 3);
  const std::vector<uint64_t> edges = SortedEdges(SmoothColor(color), color.width, color.height);
  return SegmentSortedEdges(edges, color.width, color.height, scale);
}

LabelLayers SegmentMultiscale(const DenseMap& color, int num_levels) {
  assert(color.channels == 3);
  LabelLayers layers;
  layers.width = color.width;
  layers.height = color.height;
  const std::vector<uint64_t> edges = SortedEdges(SmoothColor(color), color.width, color.height);
  for (int level = 0; level < num_levels; ++level) {
    layers.levels.push_back(
        SegmentSortedEdges(edges, color.width, color.height,
                           SegmentationScale(level, num_levels, color.width, color.height)));
  }
  return layers;
}

}  // namespace msp

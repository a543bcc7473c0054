#include "prior/graph_segmentation.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/ximgproc/segmentation.hpp>
#include <stdexcept>
#include <unordered_map>

namespace msp {
namespace {

// Gaussian kernel half width in sigmas.
constexpr float kKernelSigmas = 4.0f;

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

// Separable Gaussian blur of every plane (clamped border), times value_scale.
std::vector<float> SmoothFeatures(const DenseMap& features, const FeatureSmoothing& smoothing) {
  const int w = features.width;
  const int h = features.height;
  const size_t plane = static_cast<size_t>(w) * h;
  std::vector<float> out(plane * features.channels);
  if (!(smoothing.sigma > 0.0f)) {
    for (size_t i = 0; i < out.size(); ++i) out[i] = features.data[i] * smoothing.value_scale;
    return out;
  }
  const float sigma = smoothing.sigma;
  const int radius = static_cast<int>(std::ceil(kKernelSigmas * sigma));
  std::vector<float> kernel(2 * radius + 1);
  float sum = 0.0f;
  for (int i = -radius; i <= radius; ++i) {
    kernel[i + radius] = std::exp(-0.5f * i * i / (sigma * sigma));
    sum += kernel[i + radius];
  }
  for (float& v : kernel) v /= sum;
  std::vector<float> tmp(plane);
  for (int c = 0; c < features.channels; ++c) {
    const float* src = features.Plane(c);
    float* dst = out.data() + c * plane;
    for (int row = 0; row < h; ++row) {  // horizontal pass
      for (int col = 0; col < w; ++col) {
        float acc = 0.0f;
        for (int i = -radius; i <= radius; ++i) {
          const int x = std::clamp(col + i, 0, w - 1);
          acc += kernel[i + radius] * src[static_cast<size_t>(row) * w + x];
        }
        tmp[static_cast<size_t>(row) * w + col] = acc;
      }
    }
    for (int row = 0; row < h; ++row) {  // vertical pass
      for (int col = 0; col < w; ++col) {
        float acc = 0.0f;
        for (int i = -radius; i <= radius; ++i) {
          const int y = std::clamp(row + i, 0, h - 1);
          acc += kernel[i + radius] * tmp[static_cast<size_t>(y) * w + col];
        }
        dst[static_cast<size_t>(row) * w + col] = acc * smoothing.value_scale;
      }
    }
  }
  return out;
}

// The sorted edge list: weight bits (non-negative floats order like their
// bit patterns) in the high word, the packed edge in the low word, so one
// integer sort orders by weight with a deterministic tie-break.
std::vector<uint64_t> SortedEdges(const std::vector<float>& values, int channels, int w, int h) {
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
        for (int c = 0; c < channels; ++c) {
          const float diff = values[c * plane + p] - values[c * plane + q];
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

std::vector<std::vector<int32_t>> SegmentEmbedded(
    const DenseMap& features, const FeatureSmoothing& smoothing,
    const std::vector<GraphSegmentationScale>& scales) {
  const std::vector<uint64_t> edges = SortedEdges(
      SmoothFeatures(features, smoothing), features.channels, features.width, features.height);
  std::vector<std::vector<int32_t>> levels;
  for (const GraphSegmentationScale& scale : scales) {
    levels.push_back(SegmentSortedEdges(edges, features.width, features.height, scale));
  }
  return levels;
}

// OpenCV's implementation smooths and sorts per call; its ids start at 0,
// which the label layers reserve for "unlabelled".
std::vector<std::vector<int32_t>> SegmentOpenCv(const DenseMap& features,
                                                const FeatureSmoothing& smoothing,
                                                const std::vector<GraphSegmentationScale>& scales) {
  const int w = features.width;
  const int h = features.height;
  const int channels = features.channels;
  cv::Mat image(h, w, CV_32FC(channels));
  for (int row = 0; row < h; ++row) {
    float* dst = image.ptr<float>(row);
    for (int col = 0; col < w; ++col) {
      for (int c = 0; c < channels; ++c) {
        dst[col * channels + c] = features.At(row, col, c) * smoothing.value_scale;
      }
    }
  }
  // OpenCV replaces a sigma <= 0 by 0.001, a one-tap kernel: no smoothing.
  const double sigma = smoothing.sigma > 0.0f ? smoothing.sigma : 0.0;
  std::vector<std::vector<int32_t>> levels;
  cv::Mat labels;
  for (const GraphSegmentationScale& scale : scales) {
    cv::Ptr<cv::ximgproc::segmentation::GraphSegmentation> segmenter =
        cv::ximgproc::segmentation::createGraphSegmentation(sigma, scale.k, scale.min_size);
    segmenter->processImage(image, labels);
    assert(labels.type() == CV_32SC1 && labels.isContinuous());
    std::vector<int32_t> level(static_cast<size_t>(w) * h);
    const int32_t* src = labels.ptr<int32_t>(0);
    for (size_t i = 0; i < level.size(); ++i) level[i] = src[i] + 1;
    levels.push_back(std::move(level));
  }
  return levels;
}

}  // namespace

Segmenter SegmenterFromName(const std::string& name) {
  if (name == "opencv") return Segmenter::kOpenCv;
  if (name == "embedded") return Segmenter::kEmbedded;
  throw std::invalid_argument("unknown segmenter \"" + name + "\" (opencv or embedded)");
}

const char* SegmenterName(Segmenter segmenter) {
  return segmenter == Segmenter::kOpenCv ? "opencv" : "embedded";
}

std::vector<std::vector<int32_t>> SegmentFeatureImage(
    const DenseMap& features, const FeatureSmoothing& smoothing,
    const std::vector<GraphSegmentationScale>& scales, Segmenter segmenter) {
  assert(features.channels >= 1 && !features.data.empty());
  return segmenter == Segmenter::kOpenCv ? SegmentOpenCv(features, smoothing, scales)
                                         : SegmentEmbedded(features, smoothing, scales);
}

}  // namespace msp

#include "prior/geometry_layers.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "base/nearest_marked_pixels.h"
#include "core/prior/geometry_feature.h"

namespace msp {
namespace {

// A 1 % depth jump weighs 1, and so does an angle of about 6 degrees between
// normals: a box standing 5 % proud of a wall or a 90-degree crease weighs
// 5 and 14, while the depth and normal noise within a matched surface stays
// near 1.
constexpr core::GeometryFeatureUnits kUnits{0.01f, 0.1f};
// The depth edges are steps of one pixel: no smoothing, which would spread
// a step over several weaker edges.
constexpr FeatureSmoothing kGeometrySmoothing{0.0f, 1.0f};
// k in the units above at 640 x 480 and larger for larger images, as the
// colour levels (tau = k / |C| is measured in pixels); the smallest region is
// 1/500 of the image, as the colour scene level, and at least a 3x3 block.
constexpr float kGeometryK = 300.0f;
constexpr double kReferenceArea = 640.0 * 480.0;
constexpr double kMinSizeFraction = 1.0 / 500.0;
constexpr int kMinRegionFloor = 9;
static_assert(core::kNumGeometryLayers == 1, "one scale, GeometryScale, per geometry layer");

}  // namespace

GraphSegmentationScale GeometryScale(int width, int height) {
  const double area = static_cast<double>(width) * height;
  GraphSegmentationScale scale;
  scale.k = static_cast<float>(kGeometryK * std::max(1.0, area / kReferenceArea));
  scale.min_size =
      std::max(kMinRegionFloor, static_cast<int>(std::lround(kMinSizeFraction * area)));
  return scale;
}

DenseMap GeometryFeatureImage(const DenseMap& depth, const DenseMap& normal, int num_threads) {
  assert(depth.channels == 1 && normal.channels == 3);
  assert(depth.width == normal.width && depth.height == normal.height);
  const int w = depth.width;
  const int h = depth.height;
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<uint8_t> has(n);
  for (size_t i = 0; i < n; ++i) has[i] = core::HasGeometry(depth.data[i]) ? 1 : 0;
  const std::vector<int> source = NearestMarkedPixels(has.data(), w, h, num_threads);
  DenseMap features(w, h, core::kNumGeometryFeatures, 0.0f);
  for (size_t i = 0; i < n; ++i) {
    if (source[i] < 0) continue;  // no depth anywhere: constant features
    const size_t s = static_cast<size_t>(source[i]);
    float f[core::kNumGeometryFeatures];
    core::GeometryFeatures(depth.data[s], normal.data[s], normal.data[n + s],
                           normal.data[2 * n + s], kUnits, f);
    for (int c = 0; c < core::kNumGeometryFeatures; ++c) features.data[c * n + i] = f[c];
  }
  return features;
}

LabelLayers SegmentGeometry(const DenseMap& depth, const DenseMap& normal, Segmenter segmenter,
                            int num_threads) {
  const std::vector<GraphSegmentationScale> scales = {GeometryScale(depth.width, depth.height)};
  LabelLayers layers;
  layers.width = depth.width;
  layers.height = depth.height;
  layers.levels = SegmentFeatureImage(GeometryFeatureImage(depth, normal, num_threads),
                                      kGeometrySmoothing, scales, segmenter);
  return layers;
}

LabelLayers AppendLayers(const LabelLayers& colour, const LabelLayers& geometry) {
  assert(colour.width == geometry.width && colour.height == geometry.height);
  LabelLayers all = colour;
  all.levels.insert(all.levels.end(), geometry.levels.begin(), geometry.levels.end());
  return all;
}

}  // namespace msp

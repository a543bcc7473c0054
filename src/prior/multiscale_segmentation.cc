#include "prior/multiscale_segmentation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace msp {
namespace {

// Gaussian pre-smoothing of Felzenszwalb-Huttenlocher: sigma 0.8 removes
// sensor noise and digitisation artefacts without moving edges.
constexpr float kSmoothingSigma = 0.8f;
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

constexpr FeatureSmoothing kColorSmoothing{kSmoothingSigma, kColorScale};

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

std::vector<int32_t> SegmentGraph(const DenseMap& color, const GraphSegmentationScale& scale,
                                  Segmenter segmenter) {
  assert(color.channels == 3);
  return SegmentFeatureImage(color, kColorSmoothing, {scale}, segmenter).front();
}

LabelLayers SegmentMultiscale(const DenseMap& color, int num_levels, Segmenter segmenter) {
  assert(color.channels == 3);
  std::vector<GraphSegmentationScale> scales;
  for (int level = 0; level < num_levels; ++level) {
    scales.push_back(SegmentationScale(level, num_levels, color.width, color.height));
  }
  LabelLayers layers;
  layers.width = color.width;
  layers.height = color.height;
  layers.levels = SegmentFeatureImage(color, kColorSmoothing, scales, segmenter);
  return layers;
}

}  // namespace msp

// Embedded multi-granularity segmenter: when an image has no mask layers, the
// prior builds its own L label layers with Felzenszwalb-Huttenlocher graph
// segmentation (IJCV 2004) of the colour image at L scales, coarse to fine, so
// the method runs on a plain COLMAP workspace. Deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"
#include "prior/label_layers.h"

namespace msp {

// One granularity of the graph segmentation.
struct GraphSegmentationScale {
  // Merge threshold k of tau(C) = k / |C| on colour distances in 0..255 RGB
  // units: larger k, larger regions.
  float k = 300.0f;
  // Regions smaller than this many pixels are merged into a neighbour.
  int min_size = 50;
};

// The scale of level `level` of `num_levels` (0 = coarsest) for a
// width x height image: k and min_size interpolate geometrically between the
// scene-level and the feature-level setting, and grow with the image area
// above 640 x 480 so a level has the same granularity at every larger size.
GraphSegmentationScale SegmentationScale(int level, int num_levels, int width, int height);

// Felzenszwalb-Huttenlocher segmentation of an RGB DenseMap (3 planar
// channels in [0, 1]) on the 8-connected pixel grid after Gaussian smoothing.
// Region ids are 1..K in raster order of first appearance.
std::vector<int32_t> SegmentGraph(const DenseMap& color, const GraphSegmentationScale& scale);

// num_levels layers of `color` at SegmentationScale(0..num_levels-1). The
// edge graph is built and sorted once and reused by every level.
LabelLayers SegmentMultiscale(const DenseMap& color, int num_levels);

}  // namespace msp

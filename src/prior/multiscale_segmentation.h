// Embedded multi-granularity segmenter: when an image has no mask layers, the
// prior builds its own L colour label layers with Felzenszwalb-Huttenlocher
// graph segmentation (graph_segmentation.h) of the colour image at L scales,
// coarse to fine, so the method runs on a plain COLMAP workspace.
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"
#include "base/label_layers.h"
#include "prior/graph_segmentation.h"

namespace msp {

// The scale of level `level` of `num_levels` (0 = coarsest) for a
// width x height image: k (on colour distances in 0..255 RGB units) and
// min_size interpolate geometrically between the scene-level and the
// feature-level setting, and grow with the image area above 640 x 480 so a
// level has the same granularity at every larger size.
GraphSegmentationScale SegmentationScale(int level, int num_levels, int width, int height);

// Segmentation of an RGB DenseMap (3 planar channels in [0, 1]) after
// Gaussian smoothing (sigma 0.8). Region ids are 1..K.
std::vector<int32_t> SegmentGraph(const DenseMap& color, const GraphSegmentationScale& scale,
                                  Segmenter segmenter);

// num_levels layers of `color` at SegmentationScale(0..num_levels-1).
LabelLayers SegmentMultiscale(const DenseMap& color, int num_levels, Segmenter segmenter);

}  // namespace msp

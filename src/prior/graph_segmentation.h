// Felzenszwalb-Huttenlocher graph segmentation (IJCV 2004) of a feature image:
// the pixels are the nodes, neighbouring pixels are joined by an edge whose
// weight is the Euclidean distance of their (Gaussian-smoothed) feature
// vectors, and regions grow along the cheapest edges while an edge is no
// heavier than both regions' internal difference plus k / |C|. The colour
// layers (multiscale_segmentation.h) feed it RGB, the geometry layers
// (geometry_layers.h) depth and normals. Deterministic.
//
// Two implementations, chosen by --MspStereo.segmenter. OpenCV contrib's
// (cv::ximgproc::segmentation, 4-connected grid) is the default: on the
// bundled scene it gives the higher fused F1, mostly through segment planes
// (BENCHMARKS.md). This project's own (8-connected grid) is kept because it is
// what `--MspStereo.segmenter embedded` runs: the segmenter of the earlier
// versions, whose results it reproduces bit for bit; it also sorts an image's
// edges once for all its levels, so the three colour levels take about half
// the time of three OpenCV calls.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/dense_map.h"

namespace msp {

enum class Segmenter { kOpenCv, kEmbedded };

// "opencv" or "embedded" (the values of --MspStereo.segmenter); throws
// std::invalid_argument naming the value otherwise.
Segmenter SegmenterFromName(const std::string& name);
const char* SegmenterName(Segmenter segmenter);

// One granularity of the graph segmentation.
struct GraphSegmentationScale {
  // Merge threshold k of tau(C) = k / |C|, in the units of the edge weights:
  // larger k, larger regions.
  float k = 300.0f;
  // Regions smaller than this many pixels are merged into a neighbour.
  int min_size = 50;
};

// How a feature image becomes edge weights.
struct FeatureSmoothing {
  // Gaussian pre-smoothing in pixels; <= 0 = none.
  float sigma = 0.8f;
  // Factor applied to the smoothed features: the edge weights are distances
  // of value_scale x features (colour: 255, the scale of the usual k).
  float value_scale = 1.0f;
};

// The segmentation of `features` (any number of planar channels, finite
// values) at every scale of `scales`. Region ids are 1..K per scale, never 0.
std::vector<std::vector<int32_t>> SegmentFeatureImage(
    const DenseMap& features, const FeatureSmoothing& smoothing,
    const std::vector<GraphSegmentationScale>& scales, Segmenter segmenter);

}  // namespace msp

// Depth / normal map figures against ground truth, per image and averaged.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "base/dense_map.h"

namespace msp {
namespace eval {

// A pixel's depth is within threshold k when |d - d_gt| / d_gt <= relative[k]
// (the "1 %" / "5 %" figures), and separately when |d - d_gt| <= absolute[k]
// metres (the "2 cm" / "5 cm" figures).
struct DepthThresholds {
  double relative[2] = {0.01, 0.05};
  double absolute[2] = {0.02, 0.05};
};

// Figures over one set of pixels (the whole image, its textureless part, the
// rest, or the bands around true depth edges).
// "Complete" counts over all ground-truth pixels (missing predictions count
// as failures); "accurate" counts over valid predictions only.
struct RegionMetrics {
  int num_gt = 0;                        // pixels with ground truth
  int num_valid = 0;                     // of those, with a valid prediction (finite depth > 0)
  double valid_fraction = 0.0;           // num_valid / num_gt
  double complete[2] = {0, 0};           // fraction of num_gt within threshold k
  double accurate[2] = {0, 0};           // fraction of num_valid within threshold k
  double complete_abs[2] = {0, 0};       // as complete, absolute threshold k
  double accurate_abs[2] = {0, 0};       // as accurate, absolute threshold k
  double median_rel_error = 0.0;         // |d - d_gt| / d_gt over valid predictions
  double median_normal_error_deg = 0.0;  // over valid predictions with a non-zero normal
};

// Pixels where nothing is (a ground-truth depth of 0 in exact renders: sky,
// open background) and the share of them the map gives a depth: a surface
// with no evidence behind it. Averages pool the pixels of every image.
struct EmptyMetrics {
  int num_empty = 0;
  int num_with_depth = 0;
  double with_depth_fraction = 0.0;  // num_with_depth / num_empty
};

struct DepthMapMetrics {
  std::string name;
  bool missing = false;  // no prediction file: every figure is 0
  int width = 0;         // prediction size
  int height = 0;
  RegionMetrics all;
  RegionMetrics textureless;
  RegionMetrics textured;    // the rest of the ground-truth pixels
  RegionMetrics near_edge;   // near a true depth edge (tools/evaluate/edge_regions.h)
  RegionMetrics alike_edge;  // of those, near an edge between alike colours
  EmptyMetrics empty;        // counted only when the ground truth's 0 means "nothing there"
  int edge_band_radius = 0;  // of near_edge / alike_edge, in ground-truth pixels
  // The pictures msp_stereo --MspStereo.write_previews left for the image, as
  // (kind, path), only those that exist (ExistingPreviews, map_previews.h).
  std::vector<std::pair<std::string, std::string>> previews;
};

// The pixel sets evaluated besides the whole image: CV_8UC1 masks at
// ground-truth size, non-zero inside. An empty mask holds no pixel.
struct RegionMasks {
  cv::Mat textureless;  // the rest is `textured`
  cv::Mat near_edge;
  cv::Mat alike_edge;
};

// The prediction may be smaller than the ground truth (max_image_size): the
// ground truth and the masks are sampled nearest-neighbour at each predicted
// pixel (NearestGroundTruthIndex, io/ground_truth.h). Pixels whose
// ground truth is 0 count neither way in the regions; with `zero_is_empty`
// (GroundTruthInfo::ZeroDepthIsEmpty) they are counted in `empty`.
// `normal` or `gt_normal` may be empty (then normal errors are 0); a zero
// ground-truth normal is "none" and that pixel has no normal error.
DepthMapMetrics EvaluateDepthMap(const DenseMap& depth, const DenseMap& normal,
                                 const DenseMap& gt_depth, const DenseMap& gt_normal,
                                 const RegionMasks& masks, const DepthThresholds& thresholds,
                                 bool zero_is_empty = false);

// Mean over images of every figure. Missing maps count as zeros; an image
// whose region holds no ground-truth pixel has no figure for it and is left
// out of that region's mean (num_gt is the sum over all images).
DepthMapMetrics AverageMetrics(const std::vector<DepthMapMetrics>& maps);

}  // namespace eval
}  // namespace msp

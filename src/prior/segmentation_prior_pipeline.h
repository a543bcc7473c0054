// The segmentation prior of one reference image in one pass, as the driver
// calls it (algorithm.md 3.1-3.2): edge aggregation of the label layers by
// the anchors of the unreliable pixels (eqs. 4-5) or, switched off, the union
// of their boundaries; then CRF refinement (eq. 6) on colour and the current
// depth. Its edges confine the anchor search of the following pass.
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"
#include "core/prior/best_layer.h"
#include "options/stereo_options.h"
#include "prior/crf_refinement.h"
#include "prior/label_layers.h"
#include "prior/segmentation_prior.h"

namespace msp {

struct SegmentationPriorInput {
  const LabelLayers* layers = nullptr;  // at the working resolution of `color`
  const DenseMap* color = nullptr;      // RGB planes in [0, 1]
  const DenseMap* depth = nullptr;      // current depth, null/empty at the first pass
  float depth_min = 0.0f;
  float depth_max = 0.0f;
  // Unreliable pixels with their anchors (up to kMaxPriorAnchors each) and
  // the anchors' camera-frame points; empty before the first classification.
  const std::vector<core::PriorAnchors>* anchors = nullptr;
  // RANSAC inlier distance of eq. 4 in scene units (APD's anchor threshold).
  float inlier_distance = 0.0f;
  uint32_t image = 0;  // random stream of eq. 4: (seed, image, pass)
  uint32_t pass = 0;
};

struct SegmentationPriorTimes {
  double boundaries_s = 0.0;
  double best_layers_s = 0.0;
  double aggregation_s = 0.0;
  double refinement_s = 0.0;
};

struct SegmentationPriorResult {
  Segmentation aggregated;     // edges = B' (or the union of the B_n)
  Segmentation refined;        // empty unless edge_refinement
  std::vector<uint8_t> edges;  // what confines anchors: refined, else aggregated
  SegmentationPriorTimes times;
};

// Iterations of the eq. 4 RANSAC per layer subset (APD's anchor RANSAC: 50).
constexpr int kBestLayerRansacIterations = 50;

// Runs the prior with the switches and CRF settings of `options`
// (edge_aggregation, edge_refinement, crf_*, seed, num_threads); the caller
// checks options.segmentation_prior.
SegmentationPriorResult RunSegmentationPrior(const SegmentationPriorInput& input,
                                             const MspStereoOptions& options);

}  // namespace msp

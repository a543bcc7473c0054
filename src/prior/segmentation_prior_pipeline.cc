#include "prior/segmentation_prior_pipeline.h"

#include <cassert>
#include <chrono>

#include "base/seconds_since.h"

namespace msp {

SegmentationPriorResult RunSegmentationPrior(const SegmentationPriorInput& input,
                                             const MspStereoOptions& options) {
  assert(input.layers != nullptr && input.color != nullptr);
  const LabelLayers& layers = *input.layers;
  assert(layers.width == input.color->width && layers.height == input.color->height);
  SegmentationPriorResult result;
  auto start = std::chrono::steady_clock::now();
  if (options.edge_aggregation) {
    const std::vector<std::vector<uint8_t>> boundaries = ComputeBoundaryMaps(layers);
    result.times.boundaries_s = SecondsSince(start);
    start = std::chrono::steady_clock::now();
    BestLayerOptions best_options;
    best_options.ransac =
        core::PlaneRansacParams{input.inlier_distance, kBestLayerRansacIterations};
    best_options.seed = static_cast<uint32_t>(options.seed);
    best_options.image = input.image;
    best_options.pass = input.pass;
    best_options.num_threads = options.num_threads;
    static const std::vector<core::PriorAnchors> kNoAnchors;
    const std::vector<uint32_t> best = ChooseBestLayers(
        layers, boundaries, input.anchors != nullptr ? *input.anchors : kNoAnchors, best_options);
    result.times.best_layers_s = SecondsSince(start);
    start = std::chrono::steady_clock::now();
    result.aggregated = AggregateRegions(layers, RetainRegions(layers, best));
  } else {
    result.aggregated = UnionOfLayers(layers);
  }
  result.times.aggregation_s = SecondsSince(start);

  if (options.edge_refinement) {
    start = std::chrono::steady_clock::now();
    CrfOptions crf;
    crf.iterations = options.crf_iterations;
    crf.alpha_relative = static_cast<float>(options.crf_alpha);
    crf.beta = static_cast<float>(options.crf_beta);
    crf.unary_confidence = static_cast<float>(options.crf_unary_confidence);
    crf.num_threads = options.num_threads;
    result.refined = RefineSegmentationCrf(result.aggregated, *input.color, input.depth,
                                           input.depth_min, input.depth_max, crf);
    result.edges = result.refined.edges;
    result.times.refinement_s = SecondsSince(start);
  } else {
    result.edges = result.aggregated.edges;
  }
  return result;
}

}  // namespace msp

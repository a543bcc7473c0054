#include "prior/prior_driver.h"

#include <cassert>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "base/log.h"
#include "base/seconds_since.h"
#include "prior/crf_refinement.h"
#include "prior/geometry_layers.h"
#include "prior/multiscale_segmentation.h"

namespace msp {
namespace {

double EdgeShare(const std::vector<uint8_t>& packed) {
  if (packed.empty()) return 0.0;
  size_t count = 0;
  for (uint8_t bits : packed) count += (bits & kConfiningEdge) != 0;
  return static_cast<double>(count) / packed.size();
}

// B' of eq. 5: the regions of the layers the anchors choose (eq. 4), merged.
Segmentation AggregateByAnchors(const LabelLayers& layers, const PriorPassInput& input,
                                const MspStereoOptions& options, SegmentationPriorTimes* times) {
  auto start = std::chrono::steady_clock::now();
  const std::vector<std::vector<uint8_t>> boundaries = ComputeBoundaryMaps(layers);
  times->boundaries_s = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  BestLayerOptions best_options;
  best_options.ransac = core::PlaneRansacParams{input.inlier_distance, kBestLayerRansacIterations};
  best_options.seed = static_cast<uint32_t>(options.seed);
  best_options.image = static_cast<uint32_t>(input.view);
  best_options.pass = input.pass_id;
  best_options.num_threads = options.num_threads;
  static const std::vector<core::PriorAnchors> kNoAnchors;
  const std::vector<uint32_t> best = ChooseBestLayers(
      layers, boundaries, input.anchors != nullptr ? *input.anchors : kNoAnchors, best_options);
  times->best_layers_s = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  Segmentation aggregated = AggregateRegions(layers, RetainRegions(layers, best));
  times->aggregation_s = SecondsSince(start);
  return aggregated;
}

}  // namespace

SegmentationPriorResult RunSegmentationPrior(const LabelLayers& layers, const PriorPassInput& input,
                                             const MspStereoOptions& options) {
  assert(input.color != nullptr);
  assert(layers.width == input.color->width && layers.height == input.color->height);
  SegmentationPriorResult result;
  if (options.edge_aggregation) {
    result.aggregated = AggregateByAnchors(layers, input, options, &result.times);
  } else {
    const auto start = std::chrono::steady_clock::now();
    result.aggregated = UnionOfLayers(layers);
    result.times.aggregation_s = SecondsSince(start);
  }
  if (options.edge_refinement) {
    const auto start = std::chrono::steady_clock::now();
    CrfOptions crf;
    crf.iterations = options.advanced_crf_iterations;
    crf.alpha_relative = static_cast<float>(options.advanced_crf_alpha);
    crf.beta = static_cast<float>(options.advanced_crf_beta);
    crf.unary_confidence = static_cast<float>(options.advanced_crf_unary_confidence);
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

std::vector<uint8_t> PackPriorEdges(const SegmentationPriorResult& result) {
  std::vector<uint8_t> packed(result.edges.size(), 0);
  for (size_t i = 0; i < packed.size(); ++i) {
    uint8_t bits = result.edges[i] ? kConfiningEdge : 0;
    if (!result.aggregated.edges.empty() && result.aggregated.edges[i]) bits |= kAggregatedEdge;
    if (!result.refined.edges.empty() && result.refined.edges[i]) bits |= kRefinedEdge;
    packed[i] = bits;
  }
  return packed;
}

std::vector<uint8_t> UnpackEdgeBit(const std::vector<uint8_t>& packed, uint8_t bit) {
  std::vector<uint8_t> map(packed.size());
  for (size_t i = 0; i < packed.size(); ++i) map[i] = (packed[i] & bit) ? 1 : 0;
  return map;
}

PriorDriver::PriorDriver(const std::vector<View>& views, const MspStereoOptions& options,
                         int num_threads, size_t layer_budget_bytes)
    : views_(views),
      options_(options),
      segmenter_(SegmenterFromName(options.segmenter)),
      layer_budget_bytes_(layer_budget_bytes) {
  options_.num_threads = num_threads;
}

void PriorDriver::StartRound() {
  round_layers_.clear();
  round_layer_bytes_ = 0;
}

bool PriorDriver::FromMaskFiles(int view) const {
  const ImageLabelLayers& given = views_[view].mask_layers;
  return given.source == LabelSource::kMaskFiles && !given.layers.levels.empty();
}

const LabelLayers& PriorDriver::RoundLayers(int view, const DenseMap& color) {
  auto it = round_layers_.find(view);
  if (it != round_layers_.end()) return it->second;
  LabelLayers layers =
      FromMaskFiles(view)
          ? ResampleNearest(views_[view].mask_layers.layers, color.width, color.height)
          : SegmentMultiscale(color, options_.advanced_num_mask_levels, segmenter_);
  const size_t bytes =
      static_cast<size_t>(layers.width) * layers.height * layers.NumLevels() * sizeof(int32_t);
  if (round_layer_bytes_ + bytes > layer_budget_bytes_) {
    uncached_layers_ = std::move(layers);
    return uncached_layers_;
  }
  round_layer_bytes_ += bytes;
  return round_layers_.emplace(view, std::move(layers)).first->second;
}

void PriorDriver::LogSources(int view, int num_round_layers, bool with_geometry) {
  if (!logged_source_.insert(view).second) return;
  if (FromMaskFiles(view)) {
    Logf(kLogDetail, "  segmentation prior of %s: %d label layers from the mask files%s\n",
         views_[view].name.c_str(), num_round_layers,
         options_.geometry_layers ? " (no geometry layers: mask files decide)" : "");
    return;
  }
  Logf(kLogDetail,
       "  segmentation prior of %s: %d colour label layers from the embedded segmenter (%s)",
       views_[view].name.c_str(), num_round_layers, SegmenterName(segmenter_));
  if (with_geometry) {
    Logf(kLogDetail, " and %d geometry layer%s from the current depth and normal maps",
         core::kNumGeometryLayers, core::kNumGeometryLayers == 1 ? "" : "s");
  }
  Logf(kLogDetail, "\n");
}

std::vector<uint8_t> PriorDriver::Run(const PriorPassInput& input) {
  if (input.color == nullptr || input.color->channels != 3 || input.anchors == nullptr) {
    throw std::logic_error("PriorDriver::Run: the prior needs the colour image and the anchors");
  }
  const auto start = std::chrono::steady_clock::now();
  const LabelLayers& round_layers = RoundLayers(input.view, *input.color);
  const double layer_seconds = SecondsSince(start);
  const bool with_geometry = options_.geometry_layers && !FromMaskFiles(input.view) &&
                             input.geometry_depth != nullptr && input.geometry_normal != nullptr;
  LogSources(input.view, round_layers.NumLevels(), with_geometry);
  if (with_geometry && (input.geometry_depth->width != input.color->width ||
                        input.geometry_depth->height != input.color->height ||
                        input.geometry_normal->width != input.color->width ||
                        input.geometry_normal->height != input.color->height)) {
    throw std::logic_error("PriorDriver::Run: depth, normal and colour maps differ in size");
  }
  const auto geometry_start = std::chrono::steady_clock::now();
  LabelLayers all_layers;
  if (with_geometry) {
    all_layers =
        AppendLayers(round_layers, SegmentGeometry(*input.geometry_depth, *input.geometry_normal,
                                                   segmenter_, options_.num_threads));
  }
  const double geometry_seconds = SecondsSince(geometry_start);
  const SegmentationPriorResult result =
      RunSegmentationPrior(with_geometry ? all_layers : round_layers, input, options_);
  std::vector<uint8_t> packed = PackPriorEdges(result);
  const double seconds = SecondsSince(start);
  total_seconds_ += seconds;
  ++num_calls_;
  const SegmentationPriorTimes& t = result.times;
  Logf(kLogDetail,
       "  segmentation prior: %.3f s (layers %.3f, geometry layers %.3f, boundaries %.3f, best "
       "layers %.3f, aggregation %.3f, CRF %.3f%s), %zu anchored pixels, edges on %.1f%% of "
       "pixels\n",
       seconds, layer_seconds, geometry_seconds, t.boundaries_s, t.best_layers_s, t.aggregation_s,
       t.refinement_s, options_.edge_refinement && input.depth == nullptr ? " colour only" : "",
       input.anchors->size(), 100.0 * EdgeShare(packed));
  return packed;
}

}  // namespace msp

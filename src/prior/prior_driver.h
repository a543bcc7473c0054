// The segmentation prior as the CPU passes use it (docs/method.md section 4). Per
// reference image and round, the label layers at the round's resolution (the
// user's mask layers resampled, or the embedded segmenter on the colour
// image); per deformable pass, with the embedded layers, the geometry layers
// of the current depth and normal maps (geometry_layers.h); then edge aggregation of the layers by
// the anchors of the unreliable pixels (eqs. 4-5) or, switched off, the union of their boundaries,
// then CRF refinement (eq. 6) on colour and the current depth. The edges, packed into one byte per
// pixel (the form PixelState keeps them in between passes), confine the anchor search of the
// following passes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

#include "base/dense_map.h"
#include "base/label_layers.h"
#include "base/mvs_input.h"
#include "core/prior/best_layer.h"
#include "options/stereo_options.h"
#include "prior/graph_segmentation.h"
#include "prior/segmentation_prior.h"

namespace msp {

// Bits of the packed edge map (PixelState::edges).
constexpr uint8_t kConfiningEdge = 1;   // confines anchors: refined edges, else aggregated
constexpr uint8_t kAggregatedEdge = 2;  // B' of eq. 5, or the union of the layers (w/o Agr.)
constexpr uint8_t kRefinedEdge = 4;     // edges of the CRF-refined labels (eq. 6)

// Iterations of the eq. 4 RANSAC per layer subset (APD's anchor RANSAC: 50).
constexpr int kBestLayerRansacIterations = 50;

// What one reference image's prior needs in one pass.
struct PriorPassInput {
  int view = -1;                    // index into the views
  const DenseMap* color = nullptr;  // RGB planes in [0, 1] at the round's resolution
  const DenseMap* depth = nullptr;  // current depth; null = colour-only CRF
  // Current depth and normal maps for the geometry layers; null = colour
  // layers only (also with geometry_layers off or mask files).
  const DenseMap* geometry_depth = nullptr;
  const DenseMap* geometry_normal = nullptr;
  float depth_min = 0.0f;
  float depth_max = 0.0f;
  // Unreliable pixels with their anchors (up to kMaxPriorAnchors each) and
  // the anchors' camera-frame points; null = none.
  const std::vector<core::PriorAnchors>* anchors = nullptr;
  // RANSAC inlier distance of eq. 4 in scene units (APD's anchor threshold).
  float inlier_distance = 0.0f;
  uint32_t pass_id = 0;  // random stream of eq. 4: (seed, view, pass_id)
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

// The prior of one image in one pass on its label layers `layers` (at the
// resolution of input.color), with the switches and CRF settings of
// `options` (edge_aggregation, edge_refinement, crf_*, seed, num_threads);
// the caller checks options.segmentation_prior.
SegmentationPriorResult RunSegmentationPrior(const LabelLayers& layers, const PriorPassInput& input,
                                             const MspStereoOptions& options);

// One byte per pixel holding the three edge maps of `result`.
std::vector<uint8_t> PackPriorEdges(const SegmentationPriorResult& result);

// The 0/1 map of one bit of a packed edge map.
std::vector<uint8_t> UnpackEdgeBit(const std::vector<uint8_t>& packed, uint8_t bit);

// Runs the prior for the passes; holds the current round's label layers.
class PriorDriver {
 public:
  // `num_threads` is the resolved worker count (>= 1). The round's layers are
  // kept for the next passes while they fit `layer_budget_bytes`; the
  // layers of the images beyond are made again at each pass (the passes
  // visit the images in turn, so keeping the first ones serves best).
  PriorDriver(const std::vector<View>& views, const MspStereoOptions& options, int num_threads,
              size_t layer_budget_bytes = SIZE_MAX);

  // Drops the previous round's layers (they are at another resolution).
  void StartRound();

  // The prior of one image in one pass; returns the packed edge map at the
  // size of input.color and logs its steps' seconds.
  std::vector<uint8_t> Run(const PriorPassInput& input);

  double TotalSeconds() const { return total_seconds_; }
  int NumCalls() const { return num_calls_; }

 private:
  bool FromMaskFiles(int view) const;
  // The round's layers of the mask files or of the embedded colour segmenter.
  const LabelLayers& RoundLayers(int view, const DenseMap& color);
  void LogSources(int view, int num_round_layers, bool with_geometry);

  const std::vector<View>& views_;
  MspStereoOptions options_;  // num_threads resolved
  Segmenter segmenter_;
  std::map<int, LabelLayers> round_layers_;
  size_t layer_budget_bytes_;
  size_t round_layer_bytes_ = 0;  // of round_layers_
  LabelLayers uncached_layers_;   // the last image's beyond the budget
  std::set<int> logged_source_;
  double total_seconds_ = 0.0;
  int num_calls_ = 0;
};

}  // namespace msp

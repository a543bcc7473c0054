#include "deformable/deformable_pass.h"

#include <chrono>
#include <stdexcept>
#include <utility>

#include "base/nearest_marked_pixels.h"
#include "base/seconds_since.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "prior/prior_driver.h"

namespace msp {

core::ReliabilityParams ReliabilityAfter(int finished_pass, const MspStereoOptions& msp) {
  core::ReliabilityParams reliability = core::DefaultReliabilityParams(finished_pass);
  reliability.max_minimum_cost = static_cast<float>(msp.advanced_reliable_max_cost);
  reliability.single_min_cost = static_cast<float>(msp.advanced_reliable_single_cost);
  reliability.min_spread = static_cast<float>(msp.advanced_reliable_min_spread);
  return reliability;
}

DeformablePass::DeformablePass(const MspStereoOptions& msp, int num_threads, SweepEngine& engine)
    : msp_(msp), num_threads_(num_threads), engine_(&engine) {}

DeformableStepReport DeformablePass::Run(const Pass& pass, const core::PassParams& params,
                                         PixelState* state) {
  DeformableStepReport report;
  const auto classify_start = std::chrono::steady_clock::now();
  const ReliabilityMaps maps = StartReliability(pass, params, state);
  report.classify_seconds = SecondsSince(classify_start);
  report.classified = pass.classify_after >= 0;
  report.num_pixels = maps.width * maps.height;
  report.num_reliable = maps.num_reliable;
  report.num_unreliable = maps.num_unreliable;
  DeformableSettings settings;
  settings.anchors = core::DefaultAnchorParams(pass.round, params.depth_max - params.depth_min,
                                               msp_.advanced_anchor_max_distance);
  settings.anchors.equidistribution = msp_.equidistribution;
  settings.anchors.equidistribution_iterations = msp_.advanced_equidistribution_iterations;
  settings.cost = core::DefaultDeformableParams();
  if (msp_.disassemble_clustering) {
    // The paper quadruples the anchors per sector (4 rays, 32 hits) for the
    // clusters to form, in every round.
    settings.anchors.rays_per_sector = core::kMaxRaysPerSector;
    settings.anchors.max_anchors = core::kMaxKeptAnchors;
    settings.cost.disassemble_clustering = true;
    settings.cost.clusters = core::ClusterParams{msp_.advanced_dbscan_eta,
                                                 static_cast<float>(msp_.advanced_dbscan_gamma)};
  }
  settings.synergistic = msp_.synergistic_optimization;
  settings.synergy = core::SynergyParams{msp_.advanced_sampling_solutions,
                                         msp_.advanced_disparity_samples,
                                         static_cast<float>(msp_.advanced_disparity_step),
                                         static_cast<float>(msp_.advanced_variance_weight),
                                         msp_.advanced_profile_cost_term,
                                         msp_.advanced_sampling_local_search};
  // Local search keeps improving one solution: it runs in every iteration.
  settings.synergy_iterations = msp_.advanced_sampling_local_search ? pass.iterations : 1;
  ConfineAnchors(state->edges, maps, &settings);
  report.sweeps = engine_->DeformableIterations(params, maps, settings, pass.iterations,
                                                pass.prior ? &prior_anchors_ : nullptr);
  return report;
}

// The reliability maps the step starts with: the classes the previous pass's
// local refinement left in `state`, or (at a round start) the state
// classified here.
ReliabilityMaps DeformablePass::StartReliability(const Pass& pass, const core::PassParams& params,
                                                 PixelState* state) {
  std::vector<uint8_t> classes = std::move(state->classes);
  state->classes.clear();
  if ((pass.classify_after < 0) == classes.empty()) {
    throw std::logic_error("pass schedule and reliability classes of the state disagree");
  }
  if (pass.classify_after >= 0) {
    classes = engine_->Classify(params, ReliabilityAfter(pass.classify_after, msp_));
  }
  return MakeReliabilityMaps(std::move(classes), params.state.width, params.state.height,
                             num_threads_);
}

// The confining edges of the segmentation prior in `settings`, when the
// prior has made edges for the image (PixelState::edges, empty until then).
void DeformablePass::ConfineAnchors(const std::vector<uint8_t>& edges, const ReliabilityMaps& maps,
                                    DeformableSettings* settings) {
  if (edges.empty()) return;
  if (edges.size() != static_cast<size_t>(maps.width) * maps.height) {
    throw std::logic_error("segmentation prior edges and pixel state differ in size");
  }
  // Of the packed bits only kConfiningEdge confines.
  confining_ = UnpackEdgeBit(edges, kConfiningEdge);
  settings->edges = core::BoundaryView{confining_.data(), maps.width, maps.height, maps.width};
  nearest_edge_ = NearestMarkedPixels(confining_.data(), maps.width, maps.height, num_threads_);
  settings->nearest_edge = nearest_edge_.data();
}

}  // namespace msp

// The deformable step of a pass (docs/method.md section 3), as the CPU
// runner calls it for a pass whose schedule says PassSweeps::kDeformable:
// the state the previous pass left (upsampled at a round start) is
// classified, then unreliable pixels with anchors take the deformable update
// during the pass's iterations. The segmentation prior's edges of the image
// confine the anchor search; when the prior runs after the pass, the anchors
// of the first iteration are kept for it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/deformable/reliability.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/prior/best_layer.h"
#include "deformable/deformable_sweeps.h"
#include "engine/pass_schedule.h"
#include "engine/pixel_state.h"
#include "engine/sweep_engine.h"
#include "options/stereo_options.h"

namespace msp {

// The classification thresholds after pass `finished_pass` of a round
// (core::DefaultReliabilityParams), with the costs of the options.
core::ReliabilityParams ReliabilityAfter(int finished_pass, const MspStereoOptions& msp);

// What one step did, for the log and the tests.
struct DeformableStepReport {
  bool classified = false;  // the state was classified here, not by the previous refine
  int num_pixels = 0;
  int num_reliable = 0;
  int num_unreliable = 0;
  double classify_seconds = 0.0;  // classification or nearest-reliable map
  DeformableStats sweeps;
};

// The step of every deformable pass of a run: the whole-image parts here,
// the per-pixel parts on the back-end's SweepEngine, which keeps their
// working memory from one pass to the next.
class DeformablePass {
 public:
  // `num_threads` is the resolved worker count (>= 1). The per-pixel steps
  // (classification, anchor searches, sweeps) run on `engine`, which must
  // outlive this.
  DeformablePass(const MspStereoOptions& msp, int num_threads, SweepEngine& engine);

  // The deformable step of `pass` on the state `params` views, which is
  // `state`'s. Takes the classes the previous pass's refinement left in
  // state->classes (none when pass.classify_after >= 0: the state is then
  // classified here) and leaves it without classes; reads the prior's packed
  // edges in state->edges (empty = unconfined). Throws std::logic_error when
  // the schedule and the state disagree.
  DeformableStepReport Run(const Pass& pass, const core::PassParams& params, PixelState* state);

  // The unreliable pixels with anchors in the first iteration of the last
  // pass with pass.prior, in pixel order: what the prior reads after it.
  const std::vector<core::PriorAnchors>& prior_anchors() const { return prior_anchors_; }

 private:
  ReliabilityMaps StartReliability(const Pass& pass, const core::PassParams& params,
                                   PixelState* state);
  void ConfineAnchors(const std::vector<uint8_t>& edges, const ReliabilityMaps& maps,
                      DeformableSettings* settings);

  MspStereoOptions msp_;
  int num_threads_;
  std::vector<uint8_t> confining_;  // the confining bit of the current image, as 0/1
  std::vector<int> nearest_edge_;   // scratch: its nearest confining pixel of every pixel
  SweepEngine* engine_;
  std::vector<core::PriorAnchors> prior_anchors_;
};

}  // namespace msp

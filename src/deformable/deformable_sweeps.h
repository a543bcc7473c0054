// Whole-image steps of deformable patch matching on the CPU (APD-MVS
// baseline, docs/method.md section 3): classify every pixel after a pass, map each pixel
// to its nearest reliable pixel, and run red-black iterations in which
// unreliable pixels with anchors take the deformable update and every other
// pixel the conventional one.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/reliability.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/prior/best_layer.h"
#include "deformable/anchor_pair_cache.h"
#include "engine/deformable_step.h"

namespace msp {

// The class of every pixel of params.state (core::ClassifyPixel), rows in
// parallel: the CPU back-end's part of ClassifyState.
std::vector<uint8_t> ClassifyPixels(const core::PassParams& params,
                                    const core::ReliabilityParams& rp, int num_threads);

// Classifies every pixel of params.state under the photometric cost (the
// thresholds are NCC costs, so the geometric term is left out) and builds the
// nearest-reliable map.
ReliabilityMaps ClassifyState(const core::PassParams& params, const core::ReliabilityParams& rp,
                              int num_threads);

// The local refinement that ends a pass (LocalRefineState) fused with the
// classification of the refined state, which the next pass of the round
// starts with; returns the classes (core::LocalRefineAndClassifyPixel).
std::vector<uint8_t> LocalRefineAndClassifyState(const core::PassParams& params,
                                                 const core::ReliabilityParams& rp,
                                                 int num_threads);

// Counts and the nearest-reliable map of classes computed earlier.
ReliabilityMaps MakeReliabilityMaps(std::vector<uint8_t> classes, int width, int height,
                                    int num_threads);

// The working memory of RunDeformableCheckerboardIterations, kept by the
// caller from one call to the next (what it holds between calls means
// nothing). Fresh memory costs a page fault per page on first touch, so the
// buffers live from pass to pass instead of being taken afresh, and the
// prior's anchors are filled in place instead of grown one by one.
struct DeformableBuffers {
  std::vector<int> slot;  // pixel -> its entry in anchors and hits, -1 = none
  std::vector<core::AnchorSet> anchors;
  std::vector<core::AnchorHits> hits;
  std::vector<uint32_t> solutions;   // each anchored pixel's sampling solution
  std::vector<float> depth, normal;  // the iteration's snapshot of the planes
  std::vector<int> row_start;        // scratch of CollectPriorAnchors
  std::unique_ptr<AnchorPairCachePool> caches;
};

// The anchor slot of every pixel into *slot: unreliable pixels are numbered
// in pixel order (so the slots of a band of rows are consecutive), the
// others get -1. Returns the number of slots.
int AssignAnchorSlots(const std::vector<uint8_t>& classes, std::vector<int>* slot);

// The segmentation prior's anchors (core::PriorAnchors) of every slotted
// pixel with anchors, in pixel order, their points back-projected on
// `depth` (the snapshot the anchors were fitted on). `row_start` is scratch.
void CollectPriorAnchors(const core::Camera& cam, const std::vector<int>& slot,
                         const std::vector<core::AnchorSet>& anchors, const float* depth, int width,
                         int height, int num_threads, std::vector<int>* row_start,
                         std::vector<core::PriorAnchors>* out);

// `num_iterations` red-black iterations. Before each, the anchors of every
// unreliable pixel are fitted on a snapshot of the planes (the rays are cast
// once, in the first iteration: their hits do not change); during the
// sweeps those pixels use the deformable update, the others the conventional.
// When `prior_anchors` is given it receives, in pixel order, every unreliable
// pixel with anchors in the first iteration: the anchors and their
// camera-frame points on that snapshot (the input of eq. 4). `buffers` is
// the working memory, kept by the caller across calls (DeformableBuffers).
DeformableStats RunDeformableCheckerboardIterations(
    const core::PassParams& params, const ReliabilityMaps& maps, const DeformableSettings& settings,
    int num_iterations, int num_threads, DeformableBuffers* buffers,
    std::vector<core::PriorAnchors>* prior_anchors = nullptr);

}  // namespace msp

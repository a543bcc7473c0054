// The whole-image per-pixel steps of a pass that a back-end runs on its own
// hardware: the pass runner (patch_match/pass_runner.cc) calls them through this
// interface, so the CUDA back-end runs the same schedule with its kernels in
// place of the CPU's row loops. Every step reads and leaves the state in the
// host arrays of params.state.
#pragma once

#include <cstdint>
#include <vector>

#include "core/deformable/reliability.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/prior/best_layer.h"
#include "engine/deformable_step.h"

namespace msp {

class SweepEngine {
 public:
  virtual ~SweepEngine() = default;
  // The back-end's name in the log ("CPU", "CUDA").
  virtual const char* Name() const = 0;
  // Random planes for every pixel, then their costs (InitializeState).
  virtual void Initialize(const core::PassParams& params) = 0;
  // Every pixel's stored cost under the pass's cost function (ScoreState).
  virtual void Score(const core::PassParams& params) = 0;
  // Red-black checkerboard iterations (RunCheckerboardIterations).
  virtual void Checkerboard(const core::PassParams& params, int num_iterations) = 0;
  // The +-5 px disparity sweep with fixed normals (LocalRefineState).
  virtual void LocalRefine(const core::PassParams& params) = 0;
  // The same fused with the classification for the next pass
  // (LocalRefineAndClassifyState); returns the classes.
  virtual std::vector<uint8_t> LocalRefineAndClassify(const core::PassParams& params,
                                                      const core::ReliabilityParams& rp) = 0;
  // The reliability class of every pixel (ClassifyPixels).
  virtual std::vector<uint8_t> Classify(const core::PassParams& params,
                                        const core::ReliabilityParams& rp) = 0;
  // The deformable red-black iterations with their anchor searches
  // (RunDeformableCheckerboardIterations, whose contract this is).
  virtual DeformableStats DeformableIterations(const core::PassParams& params,
                                               const ReliabilityMaps& maps,
                                               const DeformableSettings& settings,
                                               int num_iterations,
                                               std::vector<core::PriorAnchors>* prior_anchors) = 0;
  // Called once after the last pass: figures for the log (e.g. device memory).
  virtual void Finish() {}
};

}  // namespace msp

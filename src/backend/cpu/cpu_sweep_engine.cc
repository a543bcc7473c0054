#include "backend/cpu/cpu_sweep_engine.h"

#include "patch_match/sweeps.h"

namespace msp {

void CpuSweepEngine::Initialize(const core::PassParams& params) {
  InitializeState(params, num_threads_);
}

void CpuSweepEngine::Score(const core::PassParams& params) { ScoreState(params, num_threads_); }

void CpuSweepEngine::Checkerboard(const core::PassParams& params, int num_iterations) {
  RunCheckerboardIterations(params, num_iterations, num_threads_);
}

void CpuSweepEngine::LocalRefine(const core::PassParams& params) {
  LocalRefineState(params, num_threads_);
}

std::vector<uint8_t> CpuSweepEngine::LocalRefineAndClassify(const core::PassParams& params,
                                                            const core::ReliabilityParams& rp) {
  return LocalRefineAndClassifyState(params, rp, num_threads_);
}

std::vector<uint8_t> CpuSweepEngine::Classify(const core::PassParams& params,
                                              const core::ReliabilityParams& rp) {
  return ClassifyPixels(params, rp, num_threads_);
}

DeformableStats CpuSweepEngine::DeformableIterations(
    const core::PassParams& params, const ReliabilityMaps& maps, const DeformableSettings& settings,
    int num_iterations, std::vector<core::PriorAnchors>* prior_anchors) {
  return RunDeformableCheckerboardIterations(params, maps, settings, num_iterations, num_threads_,
                                             &deformable_buffers_, prior_anchors);
}

}  // namespace msp

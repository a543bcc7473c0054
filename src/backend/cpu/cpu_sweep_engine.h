// The CPU back-end's sweep engine: the conventional sweeps of
// patch_match/sweeps.h and the deformable ones of deformable/deformable_sweeps.h,
// parallel over rows.
#pragma once

#include <cstdint>
#include <vector>

#include "deformable/deformable_sweeps.h"
#include "engine/sweep_engine.h"

namespace msp {

// The CPU's steps, parallel over rows with `num_threads` threads.
class CpuSweepEngine : public SweepEngine {
 public:
  explicit CpuSweepEngine(int num_threads) : num_threads_(num_threads) {}
  const char* Name() const override { return "CPU"; }
  void Initialize(const core::PassParams& params) override;
  void Score(const core::PassParams& params) override;
  void Checkerboard(const core::PassParams& params, int num_iterations) override;
  void LocalRefine(const core::PassParams& params) override;
  std::vector<uint8_t> LocalRefineAndClassify(const core::PassParams& params,
                                              const core::ReliabilityParams& rp) override;
  std::vector<uint8_t> Classify(const core::PassParams& params,
                                const core::ReliabilityParams& rp) override;
  DeformableStats DeformableIterations(const core::PassParams& params, const ReliabilityMaps& maps,
                                       const DeformableSettings& settings, int num_iterations,
                                       std::vector<core::PriorAnchors>* prior_anchors) override;

 private:
  int num_threads_;
  DeformableBuffers deformable_buffers_;  // kept from one deformable pass to the next
};

}  // namespace msp

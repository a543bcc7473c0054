#include "backend/device_self_check.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "backend/cpu/cpu_sweep_engine.h"
#include "core/deformable/reliability.h"

// The self-check's comparison on the CPU: the CPU's engine as the device
// agrees with itself, and a device stand-in with one step made wrong fails
// it in that step (or passes, for differences as few as near ties make).
namespace msp {
namespace {

constexpr int kNumThreads = 2;

// A device stand-in: the CPU's steps, with one of them made wrong.
class FaultyEngine : public CpuSweepEngine {
 public:
  enum class Fault { kNone, kShiftedPlanes, kThrows, kNoDeformableStep, kAllReliable };
  // kShiftedPlanes moves every `stride`-th pixel's depth 1 % after the
  // red-black iterations.
  explicit FaultyEngine(Fault fault, int stride = 1)
      : CpuSweepEngine(kNumThreads), fault_(fault), stride_(stride) {}

  void Initialize(const core::PassParams& params) override {
    if (fault_ == Fault::kThrows) {
      throw std::runtime_error(
          "sweep_kernels.cu:58: cudaGetLastError() failed: cudaErrorNoKernelImageForDevice");
    }
    CpuSweepEngine::Initialize(params);
  }
  void Checkerboard(const core::PassParams& params, int num_iterations) override {
    CpuSweepEngine::Checkerboard(params, num_iterations);
    if (fault_ != Fault::kShiftedPlanes || params.geometric) return;
    const int n = params.state.width * params.state.height;
    for (int i = 0; i < n; i += stride_) params.state.depth[i] *= 1.01f;
  }
  DeformableStats DeformableIterations(const core::PassParams& params, const ReliabilityMaps& maps,
                                       const DeformableSettings& settings, int num_iterations,
                                       std::vector<core::PriorAnchors>* prior_anchors) override {
    if (fault_ == Fault::kNoDeformableStep) return DeformableStats();
    const DeformableStats stats =
        CpuSweepEngine::DeformableIterations(params, maps, settings, num_iterations, prior_anchors);
    anchored_updates += stats.anchored_updates;
    return stats;
  }
  std::vector<uint8_t> LocalRefineAndClassify(const core::PassParams& params,
                                              const core::ReliabilityParams& rp) override {
    std::vector<uint8_t> classes = CpuSweepEngine::LocalRefineAndClassify(params, rp);
    if (fault_ == Fault::kAllReliable) classes.assign(classes.size(), core::kReliable);
    return classes;
  }

  long long anchored_updates = 0;  // of the deformable step

 private:
  Fault fault_;
  int stride_;
};

using Fault = FaultyEngine::Fault;

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(DeviceSelfCheck, TheCpuAgreesWithItselfInEveryStep) {
  FaultyEngine same(Fault::kNone);
  const SelfCheckReport report = SelfCheckAgainstCpu(same, kNumThreads);
  EXPECT_TRUE(report.passed) << report.figures;
  EXPECT_EQ(report.figures,
            "pixels differing from the CPU core: random initialisation 0.00 %, red-black "
            "iterations 0.00 %, geometric scoring and iteration 0.00 %, deformable step 0.00 %, "
            "refinement and classification 0.00 % (bound 1.00 % in each step)");
  // The deformable step's own update runs, not only the conventional one.
  EXPECT_GT(same.anchored_updates, 0);
}

// A few near ties may flip between the CPU's and the device's arithmetic:
// planes moved at under kSelfCheckMaxDifferingShare of the pixels pass, at
// more they fail, and the figures say where.
TEST(DeviceSelfCheck, PlanesThatDifferAtManyPixelsFailIt) {
  FaultyEngine few(Fault::kShiftedPlanes, 200);  // 0.5 % of the pixels
  const SelfCheckReport passed = SelfCheckAgainstCpu(few, kNumThreads);
  EXPECT_TRUE(passed.passed) << passed.figures;
  EXPECT_TRUE(Has(passed.figures, "red-black iterations 0.52 %")) << passed.figures;
  FaultyEngine many(Fault::kShiftedPlanes, 20);  // 5 %
  const SelfCheckReport failed = SelfCheckAgainstCpu(many, kNumThreads);
  EXPECT_FALSE(failed.passed);
  EXPECT_TRUE(Has(failed.figures, "red-black iterations 5.01 %")) << failed.figures;
  EXPECT_TRUE(Has(failed.figures, "(bound 1.00 % in each step)")) << failed.figures;
}

// Each later step does work on the problem: skipping the deformable
// iterations, or classes that are all reliable, fail the check.
TEST(DeviceSelfCheck, EveryStepHasPixelsToDecideOn) {
  FaultyEngine no_deformable(Fault::kNoDeformableStep);
  const SelfCheckReport deformable = SelfCheckAgainstCpu(no_deformable, kNumThreads);
  EXPECT_FALSE(deformable.passed);
  EXPECT_FALSE(Has(deformable.figures, "deformable step 0.")) << deformable.figures;
  FaultyEngine all_reliable(Fault::kAllReliable);
  const SelfCheckReport refine = SelfCheckAgainstCpu(all_reliable, kNumThreads);
  EXPECT_FALSE(refine.passed);
  EXPECT_FALSE(Has(refine.figures, "refinement and classification 0.")) << refine.figures;
}

// A CUDA error is a failed check that names the step and the error.
TEST(DeviceSelfCheck, AnErrorOnTheDeviceFailsItWithTheError) {
  FaultyEngine throws(Fault::kThrows);
  const SelfCheckReport report = SelfCheckAgainstCpu(throws, kNumThreads);
  EXPECT_FALSE(report.passed);
  EXPECT_EQ(report.figures,
            "random initialisation failed on the device: sweep_kernels.cu:58: cudaGetLastError() "
            "failed: cudaErrorNoKernelImageForDevice");
}

}  // namespace
}  // namespace msp

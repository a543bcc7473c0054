// One test per kernel family of the CUDA back-end's deformable step
// (src/backend/cuda/deformable_kernels.cu): the classification, and the anchor searches
// with the deformable sweeps, on the GPU and on the CPU from copies of the
// same state of a small synthetic scene (tests/support/block_scene.h), same
// seed; and the row bands, which must change nothing at all.
//
// Tolerances, as sweep_parity_test.cc: the kernels call the same core
// functions with the same random numbers, and the arithmetic differs only
// where the CPU takes its AVX2 + FMA path of the matching cost and in the
// last bits of the device's transcendental functions. A pixel whose two best
// candidates cost nearly the same may flip, so classes and planes agree at
// all but kMaxFlippedShare of the pixels (depth within kParityDepthTolerance
// relative). Bands run the same kernels on the same data in another
// grouping: their result is compared bit for bit.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "backend/cpu/cpu_sweep_engine.h"
#include "backend/cuda/cuda_sweep_engine.h"
#include "deformable/deformable_pass.h"
#include "engine/sweep_engine.h"
#include "tests/src/backend/cuda/gpu_skip.h"
#include "tests/src/backend/cuda/parity_checks.h"
#include "tests/support/block_scene.h"

namespace msp {
namespace {

// A band cap that splits the scene's unreliable block (16 rows of 16
// pixels) into several bands: about three rows each.
constexpr size_t kSmallBandBytes =
    3 * 16 * (sizeof(core::AnchorHits) + sizeof(core::AnchorSet) + sizeof(uint32_t));

cuda::CudaSweepEngine GpuEngine() { return cuda::CudaSweepEngine({}, 0); }

// The scene from random planes with the block unreliable: the deformable
// updates then have work to do.
void StartFromRandomPlanes(test::BlockScene* s) {
  InitializeState(s->params, test::kNumThreads);
  s->state.classes = test::BlockClasses();
}

// The deformable step of DeformablePassWithClasses on `engine`; its anchored
// updates and the prior's anchors.
struct StepResult {
  long long anchored_updates = 0;
  std::vector<core::PriorAnchors> prior_anchors;
};
StepResult RunStep(const MspStereoOptions& msp, SweepEngine* engine, test::BlockScene* s) {
  Pass pass = test::DeformablePassWithClasses();
  pass.prior = true;
  DeformablePass step(msp, 1, *engine);
  StepResult result;
  result.anchored_updates = step.Run(pass, s->params, &s->state).sweeps.anchored_updates;
  result.prior_anchors = step.prior_anchors();
  return result;
}

TEST(DeformableParity, ClassifyGivesTheSameClasses) {
  MSP_SKIP_WITHOUT_GPU();
  test::BlockScene s;
  s.SetTruePlanes();
  // Off the plane in the block: a mix of classes to agree on.
  for (int row = test::kBlockRow0; row <= test::kBlockRow1; ++row) {
    for (int col = test::kBlockCol0; col <= test::kBlockCol1; ++col) {
      s.state.depth[row * test::kWidth + col] *= 1.1f;
    }
  }
  const core::ReliabilityParams rp = core::DefaultReliabilityParams(0);
  const std::vector<uint8_t> cpu = CpuSweepEngine(1).Classify(s.params, rp);
  const std::vector<uint8_t> gpu = GpuEngine().Classify(s.params, rp);
  ASSERT_EQ(cpu.size(), gpu.size());
  EXPECT_LE(test::DifferingShare(cpu, gpu), test::kMaxFlippedShare);
}

// Anchors of the first iteration come from the same snapshot on both, so
// they are the same; the sweeps then converge alike.
void ExpectStepParity(const MspStereoOptions& msp) {
  test::BlockScene cpu_scene, gpu_scene;
  StartFromRandomPlanes(&cpu_scene);
  StartFromRandomPlanes(&gpu_scene);
  CpuSweepEngine cpu_engine(1);
  cuda::CudaSweepEngine gpu_engine = GpuEngine();
  const StepResult cpu = RunStep(msp, &cpu_engine, &cpu_scene);
  const StepResult gpu = RunStep(msp, &gpu_engine, &gpu_scene);
  EXPECT_GT(cpu.anchored_updates, 0);
  EXPECT_TRUE(test::SameAnchorPixels(cpu.prior_anchors, gpu.prior_anchors));
  EXPECT_LE(test::FlippedShare(cpu_scene.state, gpu_scene.state), test::kMaxFlippedShare);
}

TEST(DeformableParity, AnchorsAndSweepsAsOnTheCpu) {
  MSP_SKIP_WITHOUT_GPU();
  MspStereoOptions msp;
  msp.disassemble_clustering =
      false;  // shared anchor pairs: cached on the CPU, own-plane on the GPU
  msp.synergistic_optimization = false;
  ExpectStepParity(msp);
}

TEST(DeformableParity, ClusteringAndSamplingAsOnTheCpu) {
  MSP_SKIP_WITHOUT_GPU();
  MspStereoOptions msp;
  msp.disassemble_clustering = true;  // direct anchor sums, sampling solutions
  msp.synergistic_optimization = true;
  ExpectStepParity(msp);
}

// Several bands give exactly the result of one: with and without the
// sampling solutions, which go back and forth between host and device.
TEST(DeformableParity, RowBandsChangeNothing) {
  MSP_SKIP_WITHOUT_GPU();
  for (bool synergistic : {false, true}) {
    MspStereoOptions msp;
    msp.synergistic_optimization = synergistic;
    test::BlockScene whole_scene, banded_scene;
    StartFromRandomPlanes(&whole_scene);
    StartFromRandomPlanes(&banded_scene);
    cuda::CudaSweepEngine whole = GpuEngine(), banded = GpuEngine();
    banded.LimitDeformableBandBytes(kSmallBandBytes);
    const StepResult w = RunStep(msp, &whole, &whole_scene);
    const StepResult b = RunStep(msp, &banded, &banded_scene);
    EXPECT_EQ(w.anchored_updates, b.anchored_updates) << "synergistic " << synergistic;
    EXPECT_TRUE(test::SameAnchorPixels(w.prior_anchors, b.prior_anchors))
        << "synergistic " << synergistic;
    EXPECT_EQ(whole_scene.state.depth, banded_scene.state.depth) << "synergistic " << synergistic;
    EXPECT_EQ(whole_scene.state.normal, banded_scene.state.normal);
    EXPECT_EQ(whole_scene.state.cost, banded_scene.state.cost);
    EXPECT_EQ(whole_scene.state.mask, banded_scene.state.mask);
  }
}

}  // namespace
}  // namespace msp

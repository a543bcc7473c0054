// One test per kernel family of the CUDA back-end: the GPU step and the CPU
// step on copies of the same state of a small synthetic scene (a textured
// plane seen by two source views, tests/support/plane_scene.h), same seed.
//
// Tolerances. The kernels call the same core functions with the same random
// numbers, so the hypotheses drawn are identical; the arithmetic differs only
// where the CPU takes its AVX2 + FMA path of the matching cost (the device
// runs the scalar path, without FMA contraction: --fmad=false) and in the
// last bits of the device's sqrt/exp/trigonometric functions. Hence:
// per-pixel steps that take no decision on a cost (scoring) agree to
// kCostTolerance; steps that keep the better of two costs may flip where two
// candidates cost nearly the same, so their planes agree at all but
// kMaxFlippedShare of the pixels (depth within kParityDepthTolerance relative;
// both in parity_checks.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "backend/cpu/cpu_sweep_engine.h"
#include "backend/cuda/cuda_sweep_engine.h"
#include "engine/sweep_engine.h"
#include "tests/src/backend/cuda/gpu_skip.h"
#include "tests/src/backend/cuda/parity_checks.h"
#include "tests/support/plane_scene.h"

namespace msp {
namespace {

constexpr float kCostTolerance = 1e-4f;
constexpr float kPlaneDepth = 2.0f;

// A copy of a scene's state with params pointing at it.
struct StateCopy {
  std::vector<float> depth, normal, cost;
  std::vector<uint32_t> mask;
  core::PassParams params;

  explicit StateCopy(const core::PassParams& p) : params(p) {
    const size_t n = static_cast<size_t>(p.state.width) * p.state.height;
    depth.assign(p.state.depth, p.state.depth + n);
    normal.assign(p.state.normal, p.state.normal + 3 * n);
    cost.assign(p.state.cost, p.state.cost + n);
    mask.assign(p.state.mask, p.state.mask + n);
    params.state = core::PixelStateView{depth.data(), normal.data(), cost.data(),
                                        mask.data(),  p.state.width, p.state.height};
  }
};

cuda::CudaSweepEngine GpuEngine() { return cuda::CudaSweepEngine({}, 0); }

void MakePassScene(test::PlaneScene* s) {
  test::MakeScene(kPlaneDepth, true, s);
  test::AddSourceView(test::MirroredSourceCamera(), s);
  s->params.seed = 7;
  s->params.image_id = 3;
  s->params.pass_id = 1;
}

void ExpectSameCosts(const StateCopy& cpu, const StateCopy& gpu) {
  for (size_t i = 0; i < cpu.cost.size(); ++i) {
    ASSERT_NEAR(cpu.cost[i], gpu.cost[i], kCostTolerance) << "pixel " << i;
  }
}

TEST(SweepParity, InitializeDrawsTheSameRandomPlanes) {
  MSP_SKIP_WITHOUT_GPU();
  test::PlaneScene s;
  MakePassScene(&s);
  StateCopy cpu(s.params), gpu(s.params);
  CpuSweepEngine(1).Initialize(cpu.params);
  GpuEngine().Initialize(gpu.params);
  for (size_t i = 0; i < cpu.depth.size(); ++i) {
    ASSERT_NEAR(cpu.depth[i], gpu.depth[i], 1e-5f * cpu.depth[i]) << "pixel " << i;
    for (int k = 0; k < 3; ++k) {
      const size_t j = k * cpu.depth.size() + i;
      ASSERT_NEAR(cpu.normal[j], gpu.normal[j], 1e-5f) << "pixel " << i;
    }
  }
  ExpectSameCosts(cpu, gpu);
}

TEST(SweepParity, ScoreGivesTheSameCostsInAGeometricPass) {
  MSP_SKIP_WITHOUT_GPU();
  test::PlaneScene s;
  MakePassScene(&s);
  // The sources' previous-pass depth: the plane, a little off.
  const int n = s.ref.width * s.ref.height;
  std::vector<float> source_depth(n, 1.01f * kPlaneDepth);
  for (int j = 0; j < s.params.num_src; ++j) {
    s.params.src[j].depth =
        core::ImageView{source_depth.data(), s.ref.width, s.ref.height, s.ref.width};
  }
  s.params.geometric = 1;
  StateCopy cpu(s.params), gpu(s.params);
  CpuSweepEngine(1).Score(cpu.params);
  GpuEngine().Score(gpu.params);
  EXPECT_EQ(cpu.depth, gpu.depth);  // scoring moves no plane
  ExpectSameCosts(cpu, gpu);
}

TEST(SweepParity, CheckerboardIterationsConvergeAlike) {
  MSP_SKIP_WITHOUT_GPU();
  test::PlaneScene s;
  MakePassScene(&s);
  StateCopy start(s.params);
  CpuSweepEngine(1).Initialize(start.params);
  StateCopy cpu(start.params), gpu(start.params);
  CpuSweepEngine(1).Checkerboard(cpu.params, 3);
  GpuEngine().Checkerboard(gpu.params, 3);
  EXPECT_LE(test::FlippedShare(cpu, gpu), test::kMaxFlippedShare);
}

// Unlit pixels (a block of the reference marked so) reach the device: they
// get no plane there either, and the iterations leave them empty.
TEST(SweepParity, UnlitPixelsStayEmptyOnTheDevice) {
  MSP_SKIP_WITHOUT_GPU();
  test::PlaneScene s;
  MakePassScene(&s);
  const int width = s.ref.width, height = s.ref.height;
  std::vector<uint8_t> unlit(static_cast<size_t>(width) * height, 0);
  for (int row = 0; row < height / 2; ++row) {
    for (int col = 0; col < width / 2; ++col) unlit[row * width + col] = 1;
  }
  s.params.unlit = unlit.data();
  StateCopy gpu(s.params);
  GpuEngine().Initialize(gpu.params);
  GpuEngine().Checkerboard(gpu.params, 3);
  int lit_with_plane = 0;
  for (size_t i = 0; i < unlit.size(); ++i) {
    if (unlit[i]) {
      ASSERT_EQ(gpu.depth[i], 0.0f) << "pixel " << i;
      ASSERT_EQ(gpu.cost[i], core::kMaxCost) << "pixel " << i;
    } else {
      lit_with_plane += gpu.depth[i] > 0.0f;
    }
  }
  EXPECT_EQ(lit_with_plane, static_cast<int>(unlit.size()) - width / 2 * (height / 2));
}

TEST(SweepParity, LocalRefineKeepsTheSameDepths) {
  MSP_SKIP_WITHOUT_GPU();
  test::PlaneScene s;
  MakePassScene(&s);
  // Start off the plane, so the sweep has somewhere to go.
  for (float& d : s.state_depth) d = 1.03f * kPlaneDepth;
  StateCopy cpu(s.params), gpu(s.params);
  CpuSweepEngine(1).LocalRefine(cpu.params);
  GpuEngine().LocalRefine(gpu.params);
  EXPECT_LE(test::FlippedShare(cpu, gpu), test::kMaxFlippedShare);
}

TEST(SweepParity, LocalRefineAndClassifyGivesTheSameClasses) {
  MSP_SKIP_WITHOUT_GPU();
  test::PlaneScene s;
  MakePassScene(&s);
  const core::ReliabilityParams rp = core::DefaultReliabilityParams(0);
  StateCopy cpu(s.params), gpu(s.params);
  const std::vector<uint8_t> cpu_classes = CpuSweepEngine(1).LocalRefineAndClassify(cpu.params, rp);
  const std::vector<uint8_t> gpu_classes = GpuEngine().LocalRefineAndClassify(gpu.params, rp);
  ASSERT_EQ(cpu_classes.size(), gpu_classes.size());
  EXPECT_LE(test::DifferingShare(cpu_classes, gpu_classes), test::kMaxFlippedShare);
  EXPECT_LE(test::FlippedShare(cpu, gpu), test::kMaxFlippedShare);
}

}  // namespace
}  // namespace msp

// The bundled scene at 320x240 through both back-ends with the same seed: the
// final (geometric, filtered) maps must agree. The CUDA back-end runs the CPU
// back-end's schedule with the GPU's sweeps, so the maps differ only where a
// near tie between two candidates flipped (sweep_parity_test.cc) and the
// change spread through propagation; the tolerances below bound that.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "backend/cpu/cpu_entry.h"
#include "backend/cuda/cuda_entry.h"
#include "io/workspace.h"
#include "patch_match/pass_runner.h"
#include "tests/src/backend/cuda/gpu_skip.h"
#include "tests/support/temp_dir.h"
#include "tools/scene/generate.h"

namespace msp {
namespace {

// Pixels with a depth in either map: at least this share has one in both...
constexpr double kMinSharedValidShare = 0.95;
// ...and of those, at least this share agrees within kDepthTolerance (relative).
constexpr double kMinAgreeingShare = 0.95;
constexpr double kDepthTolerance = 0.01;

class MemorySink : public MapSink {
 public:
  bool HasFinalOutput(int) const override { return false; }
  void Write(int view, const std::string& type, const DenseMap& depth,
             const DenseMap& normal) override {
    maps[{view, type}] = {depth, normal};
  }
  std::map<std::pair<int, std::string>, std::pair<DenseMap, DenseMap>> maps;
};

TEST(SceneParity, BundledSceneAt320x240GivesTheSameMapsOnBothBackEnds) {
  MSP_SKIP_WITHOUT_GPU();
  test::TempDir dir;
  scene::GeneratorOptions generator;
  generator.output = dir / "scene";
  generator.rig.width = 320;
  generator.rig.height = 240;
  generator.rig.num_cameras = 6;
  scene::GenerateScene(generator);

  StereoCommandOptions options;
  options.workspace_path = generator.output;
  options.msp.seed = 5;
  const Workspace ws = LoadWorkspace(options);
  MemorySink cpu, gpu;
  RunPatchMatchCpu(ws.views, ws.problems, options.patch_match, options.msp, dir / "cpu_scratch",
                   cpu);
  std::string why_none;
  const std::vector<DeviceInfo> devices = test::CudaDevices(&why_none);
  RunPatchMatchCuda(ws.views, ws.problems, options.patch_match, options.msp, dir / "gpu_scratch",
                    gpu, {devices.front()});

  ASSERT_EQ(cpu.maps.size(), gpu.maps.size());
  for (const auto& entry : cpu.maps) {
    if (entry.first.second != "geometric") continue;
    ASSERT_TRUE(gpu.maps.count(entry.first)) << ws.views[entry.first.first].name;
    const DenseMap& a = entry.second.first;
    const DenseMap& b = gpu.maps.at(entry.first).first;
    ASSERT_EQ(a.data.size(), b.data.size());
    int either = 0, both = 0, agree = 0;
    for (size_t i = 0; i < a.data.size(); ++i) {
      const bool va = a.data[i] > 0.0f, vb = b.data[i] > 0.0f;
      either += va || vb;
      both += va && vb;
      agree += va && vb && std::fabs(a.data[i] - b.data[i]) <= kDepthTolerance * a.data[i];
    }
    const std::string name = ws.views[entry.first.first].name;
    ASSERT_GT(either, 0) << name;
    EXPECT_GE(static_cast<double>(both) / either, kMinSharedValidShare) << name;
    EXPECT_GE(static_cast<double>(agree) / std::max(both, 1), kMinAgreeingShare) << name;
  }
}

}  // namespace
}  // namespace msp

// Throughput of the CPU back-end's building blocks, for ratios between
// versions and thread counts: NCC cost evaluations per second on one core,
// and whole red-black iterations (pixels per second) on 1 and N threads.
//
//   msp_bench_patch_match [width height num_views [ncc]]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/ncc.h"
#include "parallel_for.h"
#include "pixel_state.h"
#include "sweeps.h"
#include "synthetic_views.h"

namespace msp {
namespace {

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

core::PassParams MakeParams(const std::vector<View>& views, PixelState* state) {
  core::PassParams p{};
  p.ref_camera = views[0].camera;
  const DenseMap& ref = views[0].gray;
  p.ref_image = core::ImageView{ref.data.data(), ref.width, ref.height, ref.width};
  p.num_src = static_cast<int>(views.size()) - 1;
  for (int j = 0; j < p.num_src; ++j) {
    const View& v = views[j + 1];
    p.src[j].camera = v.camera;
    p.src[j].rel = core::ComputeRelativePose(p.ref_camera, v.camera);
    p.src[j].image = core::ImageView{v.gray.data.data(), v.gray.width, v.gray.height, v.gray.width};
    p.src[j].depth = core::ImageView{nullptr, 0, 0, 0};
  }
  p.ncc = core::NccParams{5, 2, 0, 5.0f, 0.2f};
  p.depth_min = 1.0f;
  p.depth_max = 4.0f;
  p.num_samples = 15;
  p.perturb_depth = 0.02f;
  p.perturb_normal = 0.03f;
  p.state = state->View();
  return p;
}

void Run(int width, int height, int num_views, bool ncc_only) {
  const std::vector<View> views =
      testing_support::RenderFrontoParallelPlane(width, height, num_views, 2.0f, 0.3f);
  PixelState state(width, height);
  const core::PassParams p = MakeParams(views, &state);

  // NCC kernel, one core: every pixel against source 0 with a fixed plane.
  const core::PlaneHypothesis h{2.0f, core::Vec3{0.0f, 0.0f, -1.0f}};
  auto t0 = std::chrono::steady_clock::now();
  double sink = 0.0;
  long evaluations = 0;
  for (int repeat = 0; repeat < 3; ++repeat) {
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        sink += core::ViewCost(p, 0, c, r, h);
        ++evaluations;
      }
    }
  }
  const double ncc_seconds = Seconds(t0);
  std::printf("ncc: %.3g evaluations/s on one core (%d samples each), %.1f ns/sample [%g]\n",
              evaluations / ncc_seconds, 36, 1e9 * ncc_seconds / (evaluations * 36.0),
              sink > 0 ? 1.0 : 0.0);

  if (ncc_only) return;
  // Whole iterations.
  const int threads_list[2] = {1, ResolveNumThreads(-1)};
  double per_thread_rate[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    InitializeState(p, threads_list[k]);
    t0 = std::chrono::steady_clock::now();
    RunCheckerboardIterations(p, 1, threads_list[k]);
    const double s = Seconds(t0);
    per_thread_rate[k] = width * height / s;
    std::printf("iteration: %d thread(s), %dx%d, %d sources: %.3f s, %.3g pixels/s\n",
                threads_list[k], width, height, num_views - 1, s, per_thread_rate[k]);
  }
  std::printf("speed-up %d threads / 1 thread: %.2fx\n", threads_list[1],
              per_thread_rate[1] / per_thread_rate[0]);
}

}  // namespace
}  // namespace msp

int main(int argc, char** argv) {
  const int width = argc > 1 ? std::atoi(argv[1]) : 640;
  const int height = argc > 2 ? std::atoi(argv[2]) : 480;
  const int num_views = argc > 3 ? std::atoi(argv[3]) : 10;
  const bool ncc_only = argc > 4 && std::string(argv[4]) == "ncc";
  msp::Run(width, height, num_views, ncc_only);
  return 0;
}

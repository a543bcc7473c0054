// Throughput of the CPU back-end's building blocks, for ratios between
// versions and thread counts: NCC cost evaluations per second on one core,
// one plane at a time and eight at once, the deformable cost against the conventional one, and
// whole red-black iterations (pixels per second) on 1 and N threads.
//
//   msp_bench_patch_match [width height num_views [ncc]]   (--help for the options)
#include <time.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "base/parallel_for.h"
#include "core/deformable/deformable_cost.h"
#include "core/patch_match/patch_match_kernel.h"
#include "engine/pixel_state.h"
#include "options/option_parser.h"
#include "options/tool_command_line.h"
#include "patch_match/sweeps.h"
#include "tests/support/deformable_costs.h"
#include "tests/support/synthetic_views.h"

namespace msp {
namespace {

#if defined(MSP_WINDOW_SUMS_AVX2)
constexpr bool kVectorPath = true;
#else
constexpr bool kVectorPath = false;
#endif

// Distance in pixels from the centre of the deformable cost's anchors, one per
// sector.
constexpr int kAnchorDistance = 12;
// Image sides the benchmark accepts: below the minimum the deformable cost's
// anchors leave few pixels to time; above the maximum the rendered views of a
// full source set take gigabytes.
constexpr int kMinImageSide = 32;
constexpr int kMaxImageSide = 4096;
static_assert(kMinImageSide > 2 * kAnchorDistance, "the deformable cost must time some pixels");

double ThreadCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The geometric consistency term, one core: the composed maps of the hot
// loops (ComposedReprojectionError) against the projections written out
// (ReprojectionError), on source depth maps of a fronto-parallel plane.
void BenchGeometricTerm(const core::PassParams& p, int width, int height) {
  constexpr float kDepth = 2.0f;
  std::vector<std::vector<float>> maps(p.num_src);
  for (int j = 0; j < p.num_src; ++j) {
    const core::Camera& cam = p.src[j].camera;
    maps[j].assign(static_cast<size_t>(cam.width) * cam.height, kDepth);
  }
  double seconds[2] = {0.0, 0.0};
  double sink = 0.0;
  long evaluations = 0;
  for (int composed = 0; composed < 2; ++composed) {
    const double t0 = ThreadCpuSeconds();
    evaluations = 0;
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        for (int j = 0; j < p.num_src; ++j) {
          const core::SourceView& s = p.src[j];
          const core::ImageView map{maps[j].data(), s.camera.width, s.camera.height,
                                    s.camera.width};
          sink += composed ? core::ComposedReprojectionError(s.rel, s.camera, map, c, r,
                                                             kDepth * 1.01f, 3.0f)
                           : core::ReprojectionError(p.ref_camera, s.camera, map, c, r,
                                                     kDepth * 1.01f, 3.0f);
          ++evaluations;
        }
      }
    }
    seconds[composed] = ThreadCpuSeconds() - t0;
  }
  std::printf("geometric term: %.1f ns per evaluation composed, %.1f ns written out (%.2fx) [%g]\n",
              1e9 * seconds[1] / evaluations, 1e9 * seconds[0] / evaluations,
              seconds[0] / seconds[1], sink > 0 ? 1.0 : 0.0);
}

// Eight planes per window and view, as propagation scores its candidates:
// one WindowNccCost per plane against WindowNccCosts with the planes in the
// lanes of one vector. The planes are a little apart in depth, so the lanes'
// samples land close together in the source: the favourable case, since a
// real sweep's candidates spread further.
void BenchCandidateBatch(const core::PassParams& p, int width, int height) {
  const int r0 = p.ncc.window_radius;
  double seconds[2] = {0.0, 0.0};
  double sink = 0.0;
  long evaluations = 0;
  for (int batch = 0; batch < 2; ++batch) {
    const double t0 = ThreadCpuSeconds();
    for (int r = r0; r < height - r0; ++r) {
      for (int c = r0; c < width - r0; ++c) {
        core::RefWindow w;
        core::PrepareWindow(p, c, r, &w);
        for (int j = 0; j < p.num_src; ++j) {
          core::Mat3 H[core::kWindowLanes];
          for (int k = 0; k < core::kWindowLanes; ++k) {
            const core::PlaneHypothesis h{2.0f * (1.0f + 0.002f * k),
                                          core::Vec3{0.0f, 0.0f, -1.0f}};
            H[k] = core::ComputeHomography(p.ref_camera, p.src[j].rel, h.normal,
                                           core::PlaneDistance(p.ref_camera, c, r, h));
          }
          float costs[core::kWindowLanes];
          if (batch) {
            core::WindowNccCosts(w, p.ref_image, p.src[j].image, H, 0xffu, p.ncc, costs);
          } else {
            for (int k = 0; k < core::kWindowLanes; ++k) {
              costs[k] = core::WindowNccCost(w, p.ref_image, p.src[j].image, H[k], p.ncc);
            }
          }
          for (int k = 0; k < core::kWindowLanes; ++k) sink += costs[k];
          evaluations += batch ? core::kWindowLanes : 0;
        }
      }
    }
    seconds[batch] = ThreadCpuSeconds() - t0;
  }
  std::printf(
      "ncc 8 planes per window (homographies included): one at a time %.1f ns/evaluation, all at "
      "once (WindowNccCosts) %.1f ns/evaluation, %.2fx [%g]\n",
      1e9 * seconds[0] / evaluations, 1e9 * seconds[1] / evaluations, seconds[0] / seconds[1],
      sink > 0 ? 1.0 : 0.0);
}

// The deformable cost (centre window + 8 anchor windows, paper eq. 3) against
// the conventional one on the same pixels and views, one core: the ratio is
// what a deformable update pays per view and candidate.
void BenchDeformableCost(const core::PassParams& p, int width, int height) {
  const int dx[core::kMaxAnchors] = {1, 1, 0, -1, -1, -1, 0, 1};
  const int dy[core::kMaxAnchors] = {0, 1, 1, 1, 0, -1, -1, -1};
  const core::PlaneHypothesis h{2.0f, core::Vec3{0.0f, 0.0f, -1.0f}};
  const core::DeformableParams d = core::DefaultDeformableParams();
  double seconds[2] = {0.0, 0.0};
  double sink = 0.0;
  long evaluations = 0;
  for (int r = kAnchorDistance; r < height - kAnchorDistance; ++r) {
    for (int c = kAnchorDistance; c < width - kAnchorDistance; ++c) {
      core::AnchorSet anchors{};
      anchors.count = core::kMaxAnchors;
      for (int a = 0; a < core::kMaxAnchors; ++a) {
        anchors.cols[a] = c + kAnchorDistance * dx[a];
        anchors.rows[a] = r + kAnchorDistance * dy[a];
      }
      core::DeformableWindows w;
      core::PrepareDeformableWindows(p, c, r, anchors, d, &w);
      const core::PreparedPlane plane = core::PreparePlane(p, c, r, h);
      double t0 = ThreadCpuSeconds();
      for (int j = 0; j < p.num_src; ++j) {
        sink += core::PhotometricViewCost(p, w.centre, j, plane) +
                core::GeometricTerm(p, j, c, r, plane.depth);
      }
      double t1 = ThreadCpuSeconds();
      seconds[0] += t1 - t0;
      for (int j = 0; j < p.num_src; ++j) sink += test::DeformableViewCost(p, w, j, plane, d);
      seconds[1] += ThreadCpuSeconds() - t1;
      evaluations += p.num_src;
    }
  }
  std::printf(
      "deformable cost: %.3g evaluations/s on one core (centre + %d anchor windows of %d samples), "
      "%.2fx the conventional cost's time [%g]\n",
      evaluations / seconds[1], core::kMaxAnchors,
      (2 * d.anchor_window_radius / d.anchor_window_step + 1) *
          (2 * d.anchor_window_radius / d.anchor_window_step + 1),
      seconds[1] / seconds[0], sink > 0 ? 1.0 : 0.0);
}

struct BenchOptions {
  int width = 640;
  int height = 480;
  int num_views = 10;  // the reference and num_views - 1 sources
  std::string mode = "all";
};

void CheckRange(const std::string& name, int value, int lo, int hi) {
  if (value < lo || value > hi) {
    throw OptionError("--" + name + " must be in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "], not " + std::to_string(value));
  }
}

void CheckBenchOptions(const BenchOptions& o) {
  CheckRange("width", o.width, kMinImageSide, kMaxImageSide);
  CheckRange("height", o.height, kMinImageSide, kMaxImageSide);
  CheckRange("num_views", o.num_views, 2, 1 + core::kMaxSourceViews);
}

void Run(int width, int height, int num_views, bool ncc_only) {
  const std::vector<View> views =
      test::RenderFrontoParallelPlane(width, height, num_views, 2.0f, 0.3f);
  PixelState state(width, height);
  const core::PassParams p = test::PhotometricPassParams(views, &state);

  // Matching cost on one core: every pixel against every source with a fixed
  // plane, in the general form (GeneralNccCost) and the fast one (a reference
  // window prepared once per pixel, as the sweeps do). CPU time of this
  // thread, so a busy machine disturbs the figures less than wall time would.
  const core::PlaneHypothesis h{2.0f, core::Vec3{0.0f, 0.0f, -1.0f}};
  const int per_side = 2 * p.ncc.window_radius / p.ncc.window_step + 1;
  const int samples = per_side * per_side;
  double rate[2] = {0.0, 0.0};
  for (int fast = 0; fast < 2; ++fast) {
    const double t0 = ThreadCpuSeconds();
    double sink = 0.0;
    long evaluations = 0;
    for (int r = 0; r < height; ++r) {
      for (int c = 0; c < width; ++c) {
        core::RefWindow w;
        core::PrepareWindow(p, c, r, &w);
        const float dist = core::PlaneDistance(p.ref_camera, c, r, h);
        for (int j = 0; j < p.num_src; ++j) {
          const core::SourceView& s = p.src[j];
          const core::Mat3 H = core::ComputeHomography(p.ref_camera, s.rel, h.normal, dist);
          sink += fast ? core::WindowNccCost(w, p.ref_image, s.image, H, p.ncc)
                       : core::GeneralNccCost(p.ref_image, s.image, H, c, r, p.ncc);
          ++evaluations;
        }
      }
    }
    const double seconds = ThreadCpuSeconds() - t0;
    rate[fast] = evaluations / seconds;
    std::printf("ncc %s: %.3g evaluations/s on one core (%d samples each), %.2f ns/sample [%g]\n",
                fast ? "fast (WindowNccCost)" : "general (GeneralNccCost)", rate[fast], samples,
                1e9 * seconds / (evaluations * static_cast<double>(samples)), sink > 0 ? 1.0 : 0.0);
  }
  std::printf("ncc fast / general: %.2fx (vector path: %s)\n", rate[1] / rate[0],
              kVectorPath ? "AVX2" : "off");

  BenchCandidateBatch(p, width, height);
  BenchDeformableCost(p, width, height);
  BenchGeometricTerm(p, width, height);
  if (ncc_only) return;
  // Whole iterations.
  const int threads_list[2] = {1, ResolveNumThreads(-1)};
  double per_thread_rate[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    InitializeState(p, threads_list[k]);
    const auto t0 = std::chrono::steady_clock::now();
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
  msp::BenchOptions options;
  msp::ToolCommandLine command_line(
      "Usage: msp_bench_patch_match [width height num_views [ncc]]\n"
      "       msp_bench_patch_match [--width W] [--height H] [--num_views N] [--mode ncc]",
      "Throughput of the CPU back-end's building blocks on a rendered fronto-parallel\n"
      "plane: matching-cost evaluations per second (general and fast form, one and eight\n"
      "planes at once, the deformable cost, the geometric term) on one core, then one\n"
      "red-black iteration on 1 and all threads. Bare words are width, height, num_views\n"
      "and mode, in this order.");
  command_line.Add("width", &options.width, "Image width in pixels.");
  command_line.Add("height", &options.height, "Image height in pixels.");
  command_line.Add("num_views", &options.num_views,
                   "Rendered views: the reference and num_views - 1 sources.");
  command_line.AddChoice("mode", &options.mode, {"all", "ncc"},
                         "ncc = the matching costs only; all = then the red-black iterations.");
  command_line.SetPositional({"width", "height", "num_views", "mode"});
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    msp::CheckBenchOptions(options);
  } catch (const std::exception& e) {
    std::cerr << "ERROR: " << e.what() << std::endl;
    return 1;
  }
  msp::Run(options.width, options.height, options.num_views, options.mode == "ncc");
  return 0;
}

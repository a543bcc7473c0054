#include "backend/device_self_check.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "backend/self_check_problem.h"
#include "core/deformable/reliability.h"
#include "deformable/deformable_pass.h"
#include "options/stereo_options.h"
#include "patch_match/pass_schedule.h"

namespace msp {
namespace {

// Red-black iterations of the photometric step: two leave most pixels of the
// problem on the plane and some still deciding, where flips would show.
constexpr int kPhotometricIterations = 2;
constexpr int kDeformableIterations = 2;

// What a step leaves: the state and, for a step that classifies, the classes.
struct StepResult {
  PixelState state;
  std::vector<uint8_t> classes;
};

// One step on `engine` over the params of the state it is given.
using Step = std::function<std::vector<uint8_t>(SweepEngine& engine, const core::PassParams& params,
                                                PixelState* state)>;

struct NamedStep {
  const char* name;
  bool geometric;
  Step run;
};

bool Within(float a, float b, float tolerance) { return std::fabs(a - b) <= tolerance; }

// Pixel i of both states holds the same plane, views and cost. NaN never does.
bool SamePixel(const PixelState& a, const PixelState& b, size_t i) {
  const size_t n = a.depth.size();
  if (a.mask[i] != b.mask[i]) return false;
  if (!Within(a.depth[i], b.depth[i], kSelfCheckDepthTolerance * std::fabs(a.depth[i]))) {
    return false;
  }
  for (size_t k = 0; k < 3; ++k) {
    if (!Within(a.normal[k * n + i], b.normal[k * n + i], kSelfCheckNormalTolerance)) return false;
  }
  return Within(a.cost[i], b.cost[i], kSelfCheckCostTolerance);
}

// Share of the pixels whose plane, views, cost or class differ.
double DifferingShare(const StepResult& a, const StepResult& b) {
  const size_t n = a.state.depth.size();
  if (b.state.depth.size() != n || a.classes.size() != b.classes.size()) return 1.0;
  size_t differ = 0;
  for (size_t i = 0; i < n; ++i) {
    const bool same_class = a.classes.empty() || a.classes[i] == b.classes[i];
    if (!same_class || !SamePixel(a.state, b.state, i)) ++differ;
  }
  return static_cast<double>(differ) / static_cast<double>(n);
}

StepResult RunStep(const SelfCheckProblem& problem, const NamedStep& step, const PixelState& start,
                   SweepEngine& engine) {
  StepResult result{start, {}};
  const core::PassParams params = problem.Params(step.geometric, &result.state);
  result.classes = step.run(engine, params, &result.state);
  return result;
}

std::vector<NamedStep> Steps(int num_threads) {
  const auto deformable = [num_threads](SweepEngine& engine, const core::PassParams& params,
                                        PixelState* state) {
    // A geometric pass of the first round that classifies its start, as a
    // deformable round's second pass with default options.
    Pass pass;
    pass.kind = PassKind::kGeometric;
    pass.index = 1;
    pass.start = PassStart::kPrevious;
    pass.sweeps = PassSweeps::kDeformable;
    pass.iterations = kDeformableIterations;
    pass.classify_after = 0;
    DeformablePass(MspStereoOptions(), num_threads, &engine).Run(pass, params, state);
    return std::vector<uint8_t>();
  };
  return {
      {"random initialisation", false,
       [](SweepEngine& e, const core::PassParams& p, PixelState*) {
         e.Initialize(p);
         return std::vector<uint8_t>();
       }},
      {"red-black iterations", false,
       [](SweepEngine& e, const core::PassParams& p, PixelState*) {
         e.Checkerboard(p, kPhotometricIterations);
         return std::vector<uint8_t>();
       }},
      {"geometric scoring and iteration", true,
       [](SweepEngine& e, const core::PassParams& p, PixelState*) {
         e.Score(p);
         e.Checkerboard(p, 1);
         return std::vector<uint8_t>();
       }},
      {"deformable step", true, deformable},
      {"refinement and classification", true,
       [](SweepEngine& e, const core::PassParams& p, PixelState*) {
         return e.LocalRefineAndClassify(p, core::DefaultReliabilityParams(0));
       }},
  };
}

std::string Percent(double share) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f %%", 100.0 * share);
  return text;
}

}  // namespace

SelfCheckReport SelfCheckAgainstCpu(SweepEngine& device, int num_threads) {
  const SelfCheckProblem problem;
  CpuSweepEngine cpu(num_threads);
  SelfCheckReport report;
  report.passed = true;
  std::string shares;
  PixelState start = problem.EmptyState();
  for (const NamedStep& step : Steps(num_threads)) {
    StepResult on_cpu = RunStep(problem, step, start, cpu);
    StepResult on_device;
    try {
      on_device = RunStep(problem, step, start, device);
    } catch (const std::exception& e) {
      report.passed = false;
      report.figures = std::string(step.name) + " failed on the device: " + e.what();
      return report;
    }
    const double share = DifferingShare(on_cpu, on_device);
    if (share > kSelfCheckMaxDifferingShare) report.passed = false;
    shares += (shares.empty() ? "" : ", ") + std::string(step.name) + " " + Percent(share);
    start = std::move(on_cpu.state);
  }
  report.figures = "pixels differing from the CPU core: " + shares + " (bound " +
                   Percent(kSelfCheckMaxDifferingShare) + " in each step)";
  return report;
}

}  // namespace msp

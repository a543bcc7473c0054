#include "backend/device_self_check.h"

#include <cmath>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "backend/cpu/cpu_sweep_engine.h"
#include "backend/self_check_problem.h"
#include "base/string_printf.h"
#include "core/deformable/reliability.h"
#include "deformable/deformable_pass.h"
#include "engine/pass_schedule.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

// Red-black iterations of the photometric step: two leave most pixels of the
// problem on the plane and some still deciding, where flips would show.
constexpr int kPhotometricIterations = 2;
constexpr int kDeformableIterations = 2;

// The steps, in the order they run; the geometric ones run a geometric pass.
constexpr const char* kStepNames[] = {"random initialisation", "red-black iterations",
                                      "geometric scoring and iteration", "deformable step",
                                      "refinement and classification"};
constexpr int kNumSteps = sizeof(kStepNames) / sizeof(kStepNames[0]);
constexpr int kFirstGeometricStep = 2;
static_assert(kNumSteps == 5, "RunSelfCheckStep has a case for every step");

void DeformableStep(SweepEngine& engine, const core::PassParams& params, int num_threads,
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
  DeformablePass(MspStereoOptions(), num_threads, engine).Run(pass, params, state);
}

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

std::string Percent(double share) { return StringPrintf("%.2f %%", 100.0 * share); }

}  // namespace

int NumSelfCheckSteps() { return kNumSteps; }

const char* SelfCheckStepName(int step) {
  if (step < 0 || step >= kNumSteps) throw std::out_of_range("SelfCheckStepName: no such step");
  return kStepNames[step];
}

std::vector<uint8_t> RunSelfCheckStep(int step, const SelfCheckProblem& problem,
                                      SweepEngine& engine, int num_threads, PixelState* state) {
  const core::PassParams p = problem.Params(step >= kFirstGeometricStep, state);
  switch (step) {
    case 0:
      engine.Initialize(p);
      return {};
    case 1:
      engine.Checkerboard(p, kPhotometricIterations);
      return {};
    case 2:
      engine.Score(p);
      engine.Checkerboard(p, 1);
      return {};
    case 3:
      DeformableStep(engine, p, num_threads, state);
      return {};
    case 4:
      return engine.LocalRefineAndClassify(p, core::DefaultReliabilityParams(0));
  }
  throw std::out_of_range("RunSelfCheckStep: no such step");
}

double SelfCheckDifferingShare(const PixelState& a, const std::vector<uint8_t>& a_classes,
                               const PixelState& b, const std::vector<uint8_t>& b_classes) {
  const size_t n = a.depth.size();
  if (b.depth.size() != n || a_classes.size() != b_classes.size() || n == 0) return 1.0;
  size_t differ = 0;
  for (size_t i = 0; i < n; ++i) {
    const bool same_class = a_classes.empty() || a_classes[i] == b_classes[i];
    if (!same_class || !SamePixel(a, b, i)) ++differ;
  }
  return static_cast<double>(differ) / static_cast<double>(n);
}

SelfCheckReport SelfCheckAgainstCpu(SweepEngine& device, int num_threads) {
  const SelfCheckProblem problem;
  CpuSweepEngine cpu(num_threads);
  SelfCheckReport report;
  report.passed = true;
  std::string shares;
  PixelState start = problem.EmptyState();
  for (int step = 0; step < NumSelfCheckSteps(); ++step) {
    PixelState on_cpu = start, on_device = start;
    const std::vector<uint8_t> cpu_classes =
        RunSelfCheckStep(step, problem, cpu, num_threads, &on_cpu);
    std::vector<uint8_t> device_classes;
    try {
      device_classes = RunSelfCheckStep(step, problem, device, num_threads, &on_device);
    } catch (const std::exception& e) {
      report.passed = false;
      report.figures = std::string(SelfCheckStepName(step)) + " failed on the device: " + e.what();
      return report;
    }
    const double share = SelfCheckDifferingShare(on_cpu, cpu_classes, on_device, device_classes);
    if (share > kSelfCheckMaxDifferingShare) report.passed = false;
    shares +=
        (shares.empty() ? "" : ", ") + std::string(SelfCheckStepName(step)) + " " + Percent(share);
    start = std::move(on_cpu);
  }
  report.figures = "pixels differing from the CPU core: " + shares + " (bound " +
                   Percent(kSelfCheckMaxDifferingShare) + " in each step)";
  return report;
}

}  // namespace msp

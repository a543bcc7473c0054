#include "patch_match/step_ledger.h"

#include "base/string_printf.h"
#include "core/cost/evaluation_count.h"

namespace msp {
namespace {

const char* StepName(int step) {
  constexpr const char* kNames[kNumSteps] = {"start (scores)",  "sweeps",       "local refine",
                                             "segment planes",  "planar prior", "prior",
                                             "outputs (filter)"};
  return kNames[step];
}

uint64_t Sum(const uint64_t (&by_phase)[3]) { return by_phase[0] + by_phase[1] + by_phase[2]; }

}  // namespace

bool EvaluationsCounted() {
#if defined(MSP_COUNT_EVALUATIONS)
  return true;
#else
  return false;
#endif
}

EvaluationCounts ReadEvaluationCounts() {
  EvaluationCounts c;
#if defined(MSP_COUNT_EVALUATIONS)
  const core::EvaluationCounters& g = core::g_evaluation_counters;
  for (int phase = 0; phase < core::kNumEvaluationPhases; ++phase) {
    c.windows[phase] = g.windows[phase].load();
    c.anchor_windows[phase] = g.anchor_windows[phase].load();
    c.samples[phase] = g.samples[phase].load();
  }
#endif
  return c;
}

EvaluationCounts operator-(const EvaluationCounts& a, const EvaluationCounts& b) {
  EvaluationCounts d;
  for (int phase = 0; phase < 3; ++phase) {
    d.windows[phase] = a.windows[phase] - b.windows[phase];
    d.anchor_windows[phase] = a.anchor_windows[phase] - b.anchor_windows[phase];
    d.samples[phase] = a.samples[phase] - b.samples[phase];
  }
  return d;
}

void StepLedger::Add(int round, Step step, double seconds, const EvaluationCounts& counts) {
  Cell& cell = rounds_[round].steps[static_cast<int>(step)];
  cell.seconds += seconds;
  for (int phase = 0; phase < 3; ++phase) {
    cell.counts.windows[phase] += counts.windows[phase];
    cell.counts.anchor_windows[phase] += counts.anchor_windows[phase];
    cell.counts.samples[phase] += counts.samples[phase];
  }
}

void StepLedger::AddImagePass(int round, const std::string& scale, long pixels) {
  Round& r = rounds_[round];
  r.scale = scale;
  r.pixel_passes += static_cast<double>(pixels);
}

std::string StepLedger::Format() const {
  double total = 0;
  for (const auto& round : rounds_) {
    for (const Cell& cell : round.second.steps) total += cell.seconds;
  }
  const bool counted = EvaluationsCounted();
  std::string out = "Cost model (per step; per pixel = per pixel of one image-pass)\n";
  out += StringPrintf("  %-10s %-16s %9s %6s", "round", "step", "seconds", "share");
  out += counted ? StringPrintf(" %10s %10s %10s\n", "windows/px", "anchors/px", "samples/px")
                 : "  (window counts: build with -DMSP_COUNT_EVALUATIONS=ON)\n";
  for (const auto& entry : rounds_) {
    const Round& r = entry.second;
    const double px = r.pixel_passes > 0 ? r.pixel_passes : 1.0;
    for (int step = 0; step < kNumSteps; ++step) {
      const EvaluationCounts& c = r.steps[step].counts;
      const double seconds = r.steps[step].seconds;
      out += StringPrintf("  %-10s %-16s %9.1f %5.1f%%", r.scale.c_str(), StepName(step), seconds,
                          total > 0 ? 100.0 * seconds / total : 0.0);
      out += counted ? StringPrintf(" %10.1f %10.1f %10.0f\n", Sum(c.windows) / px,
                                    Sum(c.anchor_windows) / px, Sum(c.samples) / px)
                     : "\n";
      if (static_cast<Step>(step) != Step::kSweeps) continue;
      // The per-pixel updates' phases (core::EvaluationPhase); the same rows
      // with or without counts, so that tables of both builds line up.
      constexpr const char* kPhases[3] = {"  other", "  propagation", "  refinement"};
      for (int phase : {1, 2, 0}) {
        out += StringPrintf("  %-10s %-16s %9s %6s", "", kPhases[phase], "", "");
        out += counted ? StringPrintf(" %10.1f %10.1f %10.0f\n", c.windows[phase] / px,
                                      c.anchor_windows[phase] / px, c.samples[phase] / px)
                       : "\n";
      }
    }
  }
  return out;
}

}  // namespace msp

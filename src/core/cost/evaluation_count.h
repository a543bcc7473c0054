// Counts of the window costs the steps evaluate, for the cost model
// (bench/cost_model.sh): how many matching windows (a hypothesis in one
// source view) and anchor windows each step scores, and the bilinear samples
// they fetch, which is what the time goes into. Compiled in only with
// -DMSP_COUNT_EVALUATIONS=ON, a build of its own: the shared atomic adds
// would slow the sweeps of a normal build. Host code only; on the device and
// in normal builds the macros are empty.
//
// The per-pixel updates say which of their phases a window belongs to
// (MSP_EVALUATION_PHASE): propagation candidates with view selection, or
// refinement candidates; everything else counts as kOtherPhase.
#pragma once

#if defined(MSP_COUNT_EVALUATIONS) && !defined(__CUDACC__)
#include <atomic>
#include <cstdint>

namespace msp {
namespace core {

enum EvaluationPhase { kOtherPhase = 0, kPropagationPhase = 1, kRefinementPhase = 2 };
constexpr int kNumEvaluationPhases = 3;

struct EvaluationCounters {
  std::atomic<uint64_t> windows[kNumEvaluationPhases];
  std::atomic<uint64_t> anchor_windows[kNumEvaluationPhases];
  std::atomic<uint64_t> samples[kNumEvaluationPhases];
};

inline EvaluationCounters g_evaluation_counters{};
// One per translation unit (static): an inline thread_local would be reached
// through a wrapper call at every access. A phase is set and read by the
// inlined per-pixel code of one unit, so each unit's own copy is enough.
static thread_local int t_evaluation_phase = kOtherPhase;

inline void CountWindows(std::atomic<uint64_t>* kind, uint64_t windows, uint64_t samples_each) {
  const int phase = t_evaluation_phase;
  kind[phase].fetch_add(windows, std::memory_order_relaxed);
  g_evaluation_counters.samples[phase].fetch_add(windows * samples_each,
                                                 std::memory_order_relaxed);
}

}  // namespace core
}  // namespace msp

#define MSP_COUNT_WINDOWS(n, samples_each) \
  ::msp::core::CountWindows(::msp::core::g_evaluation_counters.windows, (n), (samples_each))
#define MSP_COUNT_ANCHOR_WINDOWS(n, samples_each) \
  ::msp::core::CountWindows(::msp::core::g_evaluation_counters.anchor_windows, (n), (samples_each))
#define MSP_EVALUATION_PHASE(phase) (::msp::core::t_evaluation_phase = ::msp::core::phase)
#else
#define MSP_COUNT_WINDOWS(n, samples_each) ((void)0)
#define MSP_COUNT_ANCHOR_WINDOWS(n, samples_each) ((void)0)
#define MSP_EVALUATION_PHASE(phase) ((void)0)
#endif

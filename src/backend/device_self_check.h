// The device self-check, run before the CUDA back-end is trusted with a run:
// a small synthetic problem (self_check_problem.h) solved step by step by the
// device's engine and by the CPU's, each step from the same state (the CPU's
// result of the step before), and the two results compared pixel by pixel.
//
// The kernels call the same src/core functions with the same random numbers,
// so the two differ only where the CPU's AVX2 path of the matching cost or
// the device's last bits of sqrt/exp flip a near tie between two candidates:
// a small share of pixels (the parity tests' bound, tests/cuda/). A device
// that computes wrongly (a miscompiled kernel, a driver or hardware fault)
// differs at many, and a CUDA error fails the check with the error's text.
#pragma once

#include "backend/device_query.h"
#include "patch_match/sweep_engine.h"

namespace msp {

// Share of pixels that may differ in any step, and the per-pixel tolerances
// of "the same": depth relative, normal components and cost absolute.
constexpr double kSelfCheckMaxDifferingShare = 0.01;
constexpr float kSelfCheckDepthTolerance = 1e-3f;
constexpr float kSelfCheckNormalTolerance = 1e-3f;
constexpr float kSelfCheckCostTolerance = 1e-3f;

// Runs the problem's steps (random initialisation, red-black iterations,
// geometric scoring and an iteration, the deformable step, the refinement
// with its classification) on `device` and on a CPU engine of `num_threads`
// threads. Passed when no step differs at more than
// kSelfCheckMaxDifferingShare of the pixels; the figures give every step's
// share, or the step and the error `device` threw (it stops there).
SelfCheckReport SelfCheckAgainstCpu(SweepEngine& device, int num_threads);

}  // namespace msp

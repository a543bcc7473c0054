// The device self-check, run before the CUDA back-end is trusted with a run:
// a small synthetic problem (self_check_problem.h) solved step by step by the
// device's engine and by the CPU's, each step from the same state (the CPU's
// result of the step before), and the two results compared pixel by pixel.
//
// The kernels call the same src/core functions with the same random numbers,
// so the two differ only where the CPU's AVX2 path of the matching cost or
// the device's last bits of sqrt/exp flip a near tie between two candidates:
// a small share of pixels (the parity tests' bound, tests/src/backend/cuda/). A device
// that computes wrongly (a miscompiled kernel, a driver or hardware fault)
// differs at many, and a CUDA error fails the check with the error's text.
#pragma once

#include <cstdint>
#include <vector>

#include "backend/device_query.h"
#include "backend/self_check_problem.h"
#include "engine/pixel_state.h"
#include "engine/sweep_engine.h"

namespace msp {

// The per-pixel tolerances of "the same" result: depth relative (the parity
// tests'), normal components and cost absolute. Measured between the scalar
// and the AVX2 core on this problem (bench/core_steps.cc, run by
// tests/scalar_vs_vector.sh): where the depths agree, the normals of a near
// tie differ by up to 0.15 in a component at a handful of pixels and by less
// than 1e-6 elsewhere; the costs of the same plane by up to 9e-4 (the
// deformable cost's sums in another order). A wrong normal (sign, length) or
// cost lies far beyond these.
constexpr float kSelfCheckDepthTolerance = 1e-3f;
constexpr float kSelfCheckNormalTolerance = 0.1f;
constexpr float kSelfCheckCostTolerance = 5e-3f;
// Share of the pixels that may differ in any step. The scalar core (the
// kernels' arithmetic, less the device's last bits of sqrt/exp) against the
// AVX2 core differs at 0.20 % of them at most (geometric scoring and
// iteration; 0.10 % in the red-black and deformable steps, none in the
// others): a margin of five. A device computing wrongly differs at far more
// pixels of some step (tests/src/backend/device_self_check_test.cc).
constexpr double kSelfCheckMaxDifferingShare = 0.01;

// The check's steps, in order: random initialisation, red-black
// iterations, geometric scoring and an iteration, the deformable step, the
// refinement with its classification.
int NumSelfCheckSteps();
const char* SelfCheckStepName(int step);

// Runs step `step` of the check on `engine` over `state` (the problem's
// size; the step's start, its result on return). Returns the classes of a
// step that classifies, else nothing. `num_threads` is the CPU's share of a
// step (the deformable step's whole-image parts).
std::vector<uint8_t> RunSelfCheckStep(int step, const SelfCheckProblem& problem,
                                      SweepEngine& engine, int num_threads, PixelState* state);

// Share of the pixels of two results of a step whose plane, views or cost
// differ beyond the tolerances above, or whose class differs (1 when the
// sizes differ).
double SelfCheckDifferingShare(const PixelState& a, const std::vector<uint8_t>& a_classes,
                               const PixelState& b, const std::vector<uint8_t>& b_classes);

// Runs the steps on `device` and on a CPU engine of `num_threads` threads,
// each from the CPU's result of the step before. Passed when no step differs
// at more than kSelfCheckMaxDifferingShare of the pixels; the figures give
// every step's share, or the step and the error `device` threw (it stops
// there).
SelfCheckReport SelfCheckAgainstCpu(SweepEngine& device, int num_threads);

}  // namespace msp

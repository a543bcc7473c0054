// The cost model of a run: for every round of
// the pass schedule and every step of a pass, its seconds and, in a build
// with -DMSP_COUNT_EVALUATIONS=ON, the window costs it evaluated
// (core/cost/evaluation_count.h), printed per pixel of the round's images so
// that rounds of different scales compare. bench/cost_model.sh prints both.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace msp {

// Window costs by phase of the per-pixel updates (core::EvaluationPhase:
// other, propagation, refinement).
struct EvaluationCounts {
  uint64_t windows[3] = {0, 0, 0};
  uint64_t anchor_windows[3] = {0, 0, 0};
  uint64_t samples[3] = {0, 0, 0};
};

// True in a build that counts (-DMSP_COUNT_EVALUATIONS=ON).
bool EvaluationsCounted();
// The counts since the start of the process (zeros when not counted).
EvaluationCounts ReadEvaluationCounts();
EvaluationCounts operator-(const EvaluationCounts& a, const EvaluationCounts& b);

// The steps of a pass, in the order they run.
enum class Step {
  kStart,          // random planes or the carried-up planes rescored
  kSweeps,         // red-black iterations (checkerboard or deformable step)
  kLocalRefine,    // median filter, local disparity sweep (+ classification)
  kSegmentPlanes,  // segments offer their planes
  kPlanarPrior,    // triangles of confirmed pixels offer their planes
  kPrior,          // the segmentation prior
  kOutputs,        // output filter and writing the maps
};
constexpr int kNumSteps = 7;

class StepLedger {
 public:
  // Adds one step of one image-pass of round `round`.
  void Add(int round, Step step, double seconds, const EvaluationCounts& counts);
  // Counts the pixels of one image-pass of round `round`, the unit of the
  // per-pixel columns.
  void AddImagePass(int round, const std::string& scale, long pixels);
  // One table: per round and step, seconds and share of the run; with
  // counts, windows, anchor windows and bilinear samples per pixel-pass, and
  // the sweeps' split into propagation and refinement.
  std::string Format() const;

 private:
  struct Cell {
    double seconds = 0;
    EvaluationCounts counts;
  };
  struct Round {
    std::string scale;
    double pixel_passes = 0;
    Cell steps[kNumSteps];
  };
  std::map<int, Round> rounds_;
};

}  // namespace msp

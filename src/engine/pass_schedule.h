// The APD pass schedule of the CPU back-end as data (docs/method.md section 1.3):
// coarse-to-fine rounds, each one photometric pass and, with
// geom_consistency, three geometric passes. Each pass says how it starts,
// which sweeps it runs, whether its local refinement classifies for the next
// pass, whether the segmentation prior runs after it and what it writes.
// BuildPassSchedule is a pure function of the options and the image sizes;
// the pass runner (patch_match/pass_runner.cc) walks the list.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math/limits.h"
#include "options/stereo_options.h"

namespace msp {

// Number of halvings until the larger side is <= coarsest_size (0 when it already is).
int NumHalvings(int width, int height, int coarsest_size);

// Whether round `round` of `num_rounds` (its images' larger side `image_size`)
// restores detail on the planes the coarser rounds found, with the
// advanced_finest_* schedule: the finest round of several, and every round
// after the first at least advanced_restoring_image_size pixels large.
bool RestoringRound(const MspStereoOptions& msp, int round, int num_rounds, int image_size);

// APD schedule: 3 red-black iterations per pass, at most 3 geometric passes
// per round (--MspStereo.advanced_geometric_passes, finest_geometric_passes).
constexpr int kIterationsPerPass = 3;
constexpr int kNumGeometricPasses = 3;
// Pass ids inside a round; rounds are spaced so (round, pass) pairs are unique.
constexpr uint32_t kPassesPerRoundStride = 8;
static_assert(1 + kNumGeometricPasses <= static_cast<int>(kPassesPerRoundStride),
              "a round's passes must fit the stride of the pass ids");

enum class PassKind { kPhotometric, kGeometric };

// The state a pass starts from.
enum class PassStart {
  kRandom,     // random planes (the first pass overall), then their costs
  kUpsampled,  // the coarser round's last state carried up, rescored
  kPrevious,   // the previous pass's state of the image, rescored
};

// The red-black iterations of a pass.
enum class PassSweeps {
  kCheckerboard,  // the conventional update at every pixel
  kDeformable,    // the deformable step: unreliable pixels with anchors match deformed patches
};

// What a pass writes for an image that has no final outputs yet.
enum class PassOutput {
  kNone,
  kUnfiltered,  // the unfiltered photometric maps, input of the geometric stage (as COLMAP)
  kFinal,       // the final maps, filtered with --PatchMatchStereo.filter
};

struct Pass {
  int round = 0;  // 0 = the coarsest
  int num_rounds = 1;
  int halvings = 0;  // of the images at this round
  int index = 0;     // in the round: 0 = photometric, then the geometric passes
  PassKind kind = PassKind::kPhotometric;
  uint32_t id = 0;  // random stream: round * kPassesPerRoundStride + index
  PassStart start = PassStart::kRandom;
  PassSweeps sweeps = PassSweeps::kCheckerboard;
  int iterations = kIterationsPerPass;
  // Of the local refinement when it does not classify (core::PassParams).
  int refine_radius = core::kLocalRefineRadius;
  // Propagation scores only the views of each pixel's last selection.
  bool weighted_views_only = false;
  // Weakly textured pixels keep their planes (patch_match/held_pixels.h).
  bool hold_weak_texture = false;
  // kDeformable: -1 = the classes come from the previous pass's local
  // refinement; else the state is classified at the start with the
  // thresholds after this pass of a round (core::DefaultReliabilityParams).
  int classify_after = -1;
  // The local refinement also classifies the planes (thresholds after this
  // pass) for the next pass of the round.
  bool refine_classifies = false;
  bool segment_planes = false;  // segments offer their planes after the refinement
  bool prior = false;           // the segmentation prior runs after the pass
  PassOutput output = PassOutput::kNone;
  bool prior_preview = false;  // writes the prior preview (with kFinal)
  bool map_previews = false;   // writes the pictures of the final maps (with kFinal)
};

// Whether the segmentation prior runs at all: it confines anchors, so only
// with deformable patches.
bool SegmentationPriorEnabled(const MspStereoOptions& msp);

// Every pass of a run whose largest image is max_width x max_height, in order.
std::vector<Pass> BuildPassSchedule(const PatchMatchStereoOptions& pm, const MspStereoOptions& msp,
                                    int max_width, int max_height);

// One line per pass, e.g. "round 1/1 (scale 1/1), pass 2 geometric (id 1):
// previous state; 3 x deformable (classes from the refine); refine + classify; prior".
std::string ToString(const Pass& pass);
std::string ToString(const std::vector<Pass>& schedule);

}  // namespace msp

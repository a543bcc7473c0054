#include "engine/pass_schedule.h"

#include <algorithm>
#include <string>
#include <vector>

namespace msp {

int NumHalvings(int width, int height, int coarsest_size) {
  int halvings = 0;
  int side = std::max(width, height);
  while (side > coarsest_size) {
    side /= 2;
    ++halvings;
  }
  return halvings;
}

namespace {

// Pass `index` of round `round`; the rest of the schedule only through
// `num_passes` (passes of this round) and `coarser_passes` (of the round
// before, 0 in the first).
Pass MakePass(const PatchMatchStereoOptions& pm, const MspStereoOptions& msp, int round,
              int num_rounds, int index, int num_passes, int coarser_passes, int image_size,
              bool restoring) {
  Pass pass;
  pass.round = round;
  pass.num_rounds = num_rounds;
  pass.halvings = num_rounds - 1 - round;
  pass.index = index;
  pass.kind = index == 0 ? PassKind::kPhotometric : PassKind::kGeometric;
  pass.id = static_cast<uint32_t>(round) * kPassesPerRoundStride + static_cast<uint32_t>(index);
  const bool first = round == 0 && index == 0;
  pass.start =
      first ? PassStart::kRandom : (index == 0 ? PassStart::kUpsampled : PassStart::kPrevious);
  const bool last_round = round == num_rounds - 1;
  // The first pass has no planes to classify: it runs the conventional sweeps.
  // A restoring round (RestoringRound) restores detail on planes the coarser
  // rounds found, where pixels are dearest: fewer iterations, and the
  // conventional sweeps unless finest_deformable.
  const bool small_enough = msp.advanced_deformable_max_image_size == 0 ||
                            image_size <= msp.advanced_deformable_max_image_size;
  const bool round_deformable =
      msp.deformable && small_enough && (!restoring || msp.advanced_finest_deformable);
  const bool deformable = round_deformable && !first;
  pass.iterations = restoring ? msp.advanced_finest_iterations : msp.advanced_iterations;
  if (restoring) pass.refine_radius = msp.advanced_finest_refine_radius;
  // The selections the coarser rounds settled carry up with the planes.
  pass.weighted_views_only = restoring && msp.advanced_weighted_views_only;
  pass.sweeps = deformable ? PassSweeps::kDeformable : PassSweeps::kCheckerboard;
  // The coarser rounds chose the weakly textured pixels' planes; the
  // conventional update would only move them (the deformable step exists
  // for them).
  pass.hold_weak_texture = restoring && !deformable && msp.advanced_finest_hold_weak_texture;
  // A round's first pass classifies with the thresholds after the coarser
  // round's last pass; the others take the classes of the previous refine.
  if (deformable && index == 0) pass.classify_after = coarser_passes - 1;
  pass.refine_classifies = round_deformable && index + 1 < num_passes;
  const bool final_pass = last_round && index == num_passes - 1;
  // The prior's edges confine the passes after the one that made them, so
  // none are made in the final pass.
  pass.prior = SegmentationPriorEnabled(msp) && deformable && !final_pass;
  // Also in the final pass: its textureless pixels' normals are noise
  // after the sweeps, and the filter checks the planes against the views.
  pass.segment_planes = msp.segment_planes;
  if (final_pass) {
    pass.output = PassOutput::kFinal;
  } else if (last_round && pm.geom_consistency && index == 0) {
    pass.output = PassOutput::kUnfiltered;
  }
  pass.prior_preview = final_pass && SegmentationPriorEnabled(msp) && msp.write_previews;
  pass.map_previews = final_pass && msp.write_previews;
  return pass;
}

const char* KindName(PassKind kind) {
  return kind == PassKind::kPhotometric ? "photometric" : "geometric";
}

const char* StartName(PassStart start) {
  constexpr const char* kNames[] = {"random start", "upsampled state", "previous state"};
  return kNames[static_cast<int>(start)];
}

std::string SweepsName(const Pass& pass) {
  if (pass.sweeps == PassSweeps::kCheckerboard) return "checkerboard";
  if (pass.classify_after < 0) return "deformable (classes from the refine)";
  return "deformable (classified after pass " + std::to_string(pass.classify_after + 1) + ")";
}

const char* OutputName(PassOutput output) {
  constexpr const char* kNames[] = {"", "; writes unfiltered maps", "; writes final maps"};
  return kNames[static_cast<int>(output)];
}

}  // namespace

bool RestoringRound(const MspStereoOptions& msp, int round, int num_rounds, int image_size) {
  if (round == 0) return false;
  return round == num_rounds - 1 ||
         (msp.advanced_restoring_image_size > 0 && image_size >= msp.advanced_restoring_image_size);
}

bool SegmentationPriorEnabled(const MspStereoOptions& msp) {
  return msp.deformable && msp.segmentation_prior;
}

std::vector<Pass> BuildPassSchedule(const PatchMatchStereoOptions& pm, const MspStereoOptions& msp,
                                    int max_width, int max_height) {
  const int num_rounds = 1 + NumHalvings(max_width, max_height, msp.advanced_coarsest_image_size);
  std::vector<Pass> schedule;
  int coarser_passes = 0;
  for (int round = 0; round < num_rounds; ++round) {
    const int image_size = std::max(max_width, max_height) >> (num_rounds - 1 - round);
    const bool restoring = RestoringRound(msp, round, num_rounds, image_size);
    const int geometric =
        restoring ? msp.advanced_finest_geometric_passes : msp.advanced_geometric_passes;
    const int num_passes = 1 + (pm.geom_consistency ? geometric : 0);
    for (int index = 0; index < num_passes; ++index) {
      schedule.push_back(MakePass(pm, msp, round, num_rounds, index, num_passes, coarser_passes,
                                  image_size, restoring));
    }
    coarser_passes = num_passes;
  }
  return schedule;
}

std::string ToString(const Pass& pass) {
  std::string s = "round " + std::to_string(pass.round + 1) + "/" +
                  std::to_string(pass.num_rounds) + " (scale 1/" +
                  std::to_string(1 << pass.halvings) + "), pass " + std::to_string(pass.index + 1) +
                  " " + KindName(pass.kind) + " (id " + std::to_string(pass.id) + "): ";
  s += StartName(pass.start);
  s += "; " + std::to_string(pass.iterations) + " x " + SweepsName(pass);
  if (pass.weighted_views_only) s += " on the selected views";
  s += pass.refine_classifies ? "; refine + classify" : "; refine";
  if (pass.refine_radius != core::kLocalRefineRadius) {
    s += " (+-" + std::to_string(pass.refine_radius) + " px)";
  }
  if (pass.hold_weak_texture) s += "; weak texture held";
  if (pass.segment_planes) s += "; segment planes";
  if (pass.prior) s += "; prior";
  s += OutputName(pass.output);
  if (pass.map_previews) s += "; map previews";
  if (pass.prior_preview) s += "; prior preview";
  return s;
}

std::string ToString(const std::vector<Pass>& schedule) {
  std::string s;
  for (const Pass& pass : schedule) s += ToString(pass) + "\n";
  return s;
}

}  // namespace msp

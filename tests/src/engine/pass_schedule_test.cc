#include "engine/pass_schedule.h"

#include <gtest/gtest.h>

#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace msp {
namespace {

TEST(PassSchedule, NumHalvings) {
  EXPECT_EQ(NumHalvings(640, 480, 1000), 0);
  EXPECT_EQ(NumHalvings(1536, 1024, 1000), 1);
  EXPECT_EQ(NumHalvings(4000, 3000, 1000), 2);
}

// The default options with deformable patches on (off by default), whose
// schedule and outputs these tests pin down.
MspStereoOptions WithDeformable() {
  MspStereoOptions msp;
  msp.deformable = true;
  return msp;
}

// The bundled scene at --PatchMatchStereo.max_image_size 320.
constexpr int kSceneWidth = 320;
constexpr int kSceneHeight = 240;

// Options whose pyramid has one round at the scene's size, with the
// deformable step at any size and the finest round's own narrowing off.
MspStereoOptions OneRound() {
  MspStereoOptions msp = WithDeformable();
  msp.advanced_coarsest_image_size = 1000;
  msp.advanced_deformable_max_image_size = 0;
  msp.advanced_weighted_views_only = false;
  msp.advanced_finest_refine_radius = core::kLocalRefineRadius;
  return msp;
}

// The schedule's printout, also on stdout for the test log.
std::string Printed(const PatchMatchStereoOptions& pm, const MspStereoOptions& msp,
                    int width = kSceneWidth, int height = kSceneHeight) {
  const std::string printed = ToString(BuildPassSchedule(pm, msp, width, height));
  std::cout << printed;
  return printed;
}

TEST(PassSchedule, OneRound) {
  EXPECT_EQ(Printed(PatchMatchStereoOptions(), OneRound()),
            "round 1/1 (scale 1/1), pass 1 photometric (id 0): random start; 3 x checkerboard; "
            "refine + classify; segment planes; writes unfiltered maps\n"
            "round 1/1 (scale 1/1), pass 2 geometric (id 1): previous state; 3 x deformable "
            "(classes from the refine); refine + classify; segment planes; prior\n"
            "round 1/1 (scale 1/1), pass 3 geometric (id 2): previous state; 3 x deformable "
            "(classes from the refine); refine + classify; segment planes; prior\n"
            "round 1/1 (scale 1/1), pass 4 geometric (id 3): previous state; 3 x deformable "
            "(classes from the refine); refine; segment planes; writes final maps\n");
}

// Default options run the conventional core: no deformable pass, no prior.
TEST(PassSchedule, DefaultOptionsRunNoDeformablePassAndNoPrior) {
  for (const Pass& pass :
       BuildPassSchedule(PatchMatchStereoOptions(), MspStereoOptions(), 640, 480)) {
    EXPECT_EQ(pass.sweeps, PassSweeps::kCheckerboard) << ToString(pass);
    EXPECT_FALSE(pass.prior) << ToString(pass);
    EXPECT_FALSE(pass.refine_classifies) << ToString(pass);
  }
}

// The method's options at 320 x 240: 320 -> 160 -> 80; the finest round
// restores detail with one conventional iteration per pass.
TEST(PassSchedule, TheMethodRestoresDetailInTheFinestRound) {
  const std::string round1 =
      "round 1/3 (scale 1/4), pass 1 photometric (id 0): random start; 3 x checkerboard; "
      "refine + classify; segment planes\n"
      "round 1/3 (scale 1/4), pass 2 geometric (id 1): previous state; 3 x deformable "
      "(classes from the refine); refine + classify; segment planes; prior\n"
      "round 1/3 (scale 1/4), pass 3 geometric (id 2): previous state; 3 x deformable "
      "(classes from the refine); refine + classify; segment planes; prior\n"
      "round 1/3 (scale 1/4), pass 4 geometric (id 3): previous state; 3 x deformable "
      "(classes from the refine); refine; segment planes; prior\n";
  // Above deformable_max_image_size (80): conventional.
  const std::string round2 =
      "round 2/3 (scale 1/2), pass 1 photometric (id 8): upsampled state; 3 x checkerboard; "
      "refine; segment planes\n"
      "round 2/3 (scale 1/2), pass 2 geometric (id 9): previous state; 3 x checkerboard; "
      "refine; segment planes\n"
      "round 2/3 (scale 1/2), pass 3 geometric (id 10): previous state; 3 x checkerboard; "
      "refine; segment planes\n"
      "round 2/3 (scale 1/2), pass 4 geometric (id 11): previous state; 3 x checkerboard; "
      "refine; segment planes\n";
  // The finest round sweeps +-2 px in its local refinement.
  const std::string round3 =
      "round 3/3 (scale 1/1), pass 1 photometric (id 16): upsampled state; 1 x checkerboard on "
      "the selected views; refine (+-2 px); weak texture held; segment planes; writes unfiltered "
      "maps\n"
      "round 3/3 (scale 1/1), pass 2 geometric (id 17): previous state; 1 x checkerboard on the "
      "selected views; refine (+-2 px); weak texture held; segment planes\n"
      "round 3/3 (scale 1/1), pass 3 geometric (id 18): previous state; 1 x checkerboard on the "
      "selected views; refine (+-2 px); weak texture held; segment planes\n"
      "round 3/3 (scale 1/1), pass 4 geometric (id 19): previous state; 1 x checkerboard on the "
      "selected views; refine (+-2 px); weak texture held; segment planes; writes final maps\n";
  EXPECT_EQ(Printed(PatchMatchStereoOptions(), WithDeformable()), round1 + round2 + round3);
}

// weighted_views_only narrows the propagation of the finest round only,
// whose selections the coarser rounds settled; never with one round.
TEST(PassSchedule, WeightedViewsOnlyInTheFinestRound) {
  MspStereoOptions msp = WithDeformable();
  msp.advanced_weighted_views_only = true;
  const std::vector<Pass> schedule =
      BuildPassSchedule(PatchMatchStereoOptions(), msp, kSceneWidth, kSceneHeight);
  ASSERT_EQ(schedule.size(), 12u);
  for (const Pass& pass : schedule) {
    EXPECT_EQ(pass.weighted_views_only, pass.round == 2) << ToString(pass);
  }
  EXPECT_NE(Printed(PatchMatchStereoOptions(), msp)
                .find("round 3/3 (scale 1/1), pass 1 photometric (id 16): upsampled state; 1 x "
                      "checkerboard on the selected views;"),
            std::string::npos);
  MspStereoOptions one_round = OneRound();
  one_round.advanced_weighted_views_only = true;
  for (const Pass& pass :
       BuildPassSchedule(PatchMatchStereoOptions(), one_round, kSceneWidth, kSceneHeight)) {
    EXPECT_FALSE(pass.weighted_views_only);
  }
}

// The finest round of several leaves the weakly textured pixels the planes
// carried up; one round has no planes carried up to hold.
TEST(PassSchedule, WeakTextureHeldInTheFinestRoundOnly) {
  for (const Pass& pass :
       BuildPassSchedule(PatchMatchStereoOptions(), MspStereoOptions(), 640, 480)) {
    EXPECT_EQ(pass.hold_weak_texture, pass.round == pass.num_rounds - 1) << ToString(pass);
  }
  for (const Pass& pass :
       BuildPassSchedule(PatchMatchStereoOptions(), OneRound(), kSceneWidth, kSceneHeight)) {
    EXPECT_FALSE(pass.hold_weak_texture) << ToString(pass);
  }
  MspStereoOptions msp;
  msp.advanced_finest_hold_weak_texture = false;
  for (const Pass& pass : BuildPassSchedule(PatchMatchStereoOptions(), msp, 640, 480)) {
    EXPECT_FALSE(pass.hold_weak_texture) << ToString(pass);
  }
}

// Passes and iterations per round: the coarser rounds and the finest of
// several each take their own; a round's first deformable pass classifies
// with the thresholds after the coarser round's last pass.
TEST(PassSchedule, PassesAndIterationsPerRound) {
  MspStereoOptions msp = WithDeformable();
  msp.advanced_geometric_passes = 2;
  msp.advanced_finest_geometric_passes = 1;
  msp.advanced_iterations = 2;
  msp.advanced_finest_iterations = 1;
  msp.advanced_finest_deformable = true;
  msp.advanced_deformable_max_image_size = 0;
  const std::vector<Pass> schedule =
      BuildPassSchedule(PatchMatchStereoOptions(), msp, kSceneWidth, kSceneHeight);
  // Rounds at 80, 160 (3 passes each) and 320 px (2 passes).
  ASSERT_EQ(schedule.size(), 3u + 3u + 2u);
  for (const Pass& pass : schedule) {
    EXPECT_EQ(pass.iterations, pass.round == 2 ? 1 : 2) << ToString(pass);
    EXPECT_EQ(pass.index, pass.round == 2 ? static_cast<int>(&pass - &schedule[6])
                                          : static_cast<int>(&pass - &schedule[3 * pass.round]));
  }
  EXPECT_EQ(schedule[3].classify_after, 2);             // round 2 after round 1's third pass
  EXPECT_EQ(schedule[6].classify_after, 2);             // round 3 after round 2's third pass
  EXPECT_TRUE(schedule[5].refine_classifies == false);  // a round's last pass
  EXPECT_EQ(schedule.back().output, PassOutput::kFinal);
  EXPECT_EQ(schedule[6].output, PassOutput::kUnfiltered);
}

// With advanced_restoring_image_size (600), every round after the first at
// least that large restores detail as the finest round does; the first round
// never does, and 0 leaves the finest round alone.
TEST(PassSchedule, RoundsFromAnImageSizeRestoreDetail) {
  MspStereoOptions msp;
  ASSERT_EQ(msp.advanced_restoring_image_size, 600);
  // 1536x1024: rounds at 48, 96, 192, 384, 768 and 1536 px.
  const std::vector<Pass> schedule = BuildPassSchedule(PatchMatchStereoOptions(), msp, 1536, 1024);
  ASSERT_EQ(schedule.size(), 6u * 4u);
  for (const Pass& pass : schedule) {
    const bool restoring = pass.round >= 4;
    EXPECT_EQ(pass.iterations, restoring ? 1 : 3) << ToString(pass);
    EXPECT_EQ(pass.weighted_views_only, restoring) << ToString(pass);
    EXPECT_EQ(pass.hold_weak_texture, restoring) << ToString(pass);
  }
  EXPECT_EQ(schedule[5 * 4].output, PassOutput::kUnfiltered);  // the finest round writes
  EXPECT_EQ(schedule[4 * 4].output, PassOutput::kNone);
  msp.advanced_restoring_image_size = 1;  // never the first round
  EXPECT_FALSE(RestoringRound(msp, 0, 6, 48));
  EXPECT_TRUE(RestoringRound(msp, 1, 6, 96));
  msp.advanced_restoring_image_size = 0;  // the finest round only
  EXPECT_FALSE(RestoringRound(msp, 4, 6, 768));
  EXPECT_TRUE(RestoringRound(msp, 5, 6, 1536));
  // At 640x480 only the finest round is 600 px or larger: the schedule is as with 0.
  EXPECT_EQ(ToString(BuildPassSchedule(PatchMatchStereoOptions(), msp, 640, 480)),
            ToString(BuildPassSchedule(PatchMatchStereoOptions(), MspStereoOptions(), 640, 480)));
}

// Rounds above deformable_max_image_size run the conventional sweeps, and
// the prior (which confines anchors) runs only after deformable passes.
TEST(PassSchedule, DeformableOnlyUpToAnImageSize) {
  MspStereoOptions msp = WithDeformable();
  msp.advanced_deformable_max_image_size = 160;
  msp.advanced_finest_deformable = true;
  const std::vector<Pass> schedule = BuildPassSchedule(PatchMatchStereoOptions(), msp, 640, 480);
  ASSERT_EQ(schedule.size(), 16u);  // rounds at 80, 160, 320 and 640 px
  for (const Pass& pass : schedule) {
    const bool deformable = pass.round <= 1 && !(pass.round == 0 && pass.index == 0);
    EXPECT_EQ(pass.sweeps == PassSweeps::kDeformable, deformable) << ToString(pass);
    EXPECT_EQ(pass.prior, deformable) << ToString(pass);
  }
}

TEST(PassSchedule, WithoutGeometricConsistencyOnePassWritesTheFinalMaps) {
  PatchMatchStereoOptions pm;
  pm.geom_consistency = false;
  EXPECT_EQ(Printed(pm, OneRound()),
            "round 1/1 (scale 1/1), pass 1 photometric (id 0): random start; 3 x checkerboard; "
            "refine; segment planes; writes final maps\n");
}

TEST(PassSchedule, WithoutDeformablePatchesNeitherClassesNorPrior) {
  MspStereoOptions msp = OneRound();
  msp.deformable = false;
  // The prior preview needs the prior, which needs deformable patches; the
  // pictures of the final maps need neither.
  msp.write_previews = true;
  EXPECT_EQ(Printed(PatchMatchStereoOptions(), msp),
            "round 1/1 (scale 1/1), pass 1 photometric (id 0): random start; 3 x checkerboard; "
            "refine; segment planes; writes unfiltered maps\n"
            "round 1/1 (scale 1/1), pass 2 geometric (id 1): previous state; 3 x checkerboard; "
            "refine; segment planes\n"
            "round 1/1 (scale 1/1), pass 3 geometric (id 2): previous state; 3 x checkerboard; "
            "refine; segment planes\n"
            "round 1/1 (scale 1/1), pass 4 geometric (id 3): previous state; 3 x checkerboard; "
            "refine; segment planes; writes final maps; map previews\n");
}

TEST(PassSchedule, SeveralRoundsWithoutGeometricConsistencyClassifyAtEachRoundStart) {
  PatchMatchStereoOptions pm;
  pm.geom_consistency = false;
  MspStereoOptions msp = OneRound();  // 1500 -> 750: two rounds
  msp.advanced_finest_deformable = true;
  msp.advanced_finest_iterations = 3;
  msp.segment_planes = false;
  msp.write_previews = true;
  // The prior preview shows the prior's edges: without the prior there is none.
  for (bool prior : {true, false}) {
    msp.segmentation_prior = prior;
    EXPECT_EQ(Printed(pm, msp, 1500, 1000),
              "round 1/2 (scale 1/2), pass 1 photometric (id 0): random start; 3 x checkerboard; "
              "refine\n"
              "round 2/2 (scale 1/1), pass 1 photometric (id 8): upsampled state; 3 x deformable "
              "(classified after pass 1); refine; writes final maps; map previews" +
                  std::string(prior ? "; prior preview" : "") + "\n");
  }
}

// Invariants the runner relies on, over the option combinations.
TEST(PassSchedule, ClassesAndIdsAreConsistent) {
  for (const bool geom : {false, true}) {
    for (const int variant : {0, 1, 2}) {
      PatchMatchStereoOptions pm;
      pm.geom_consistency = geom;
      MspStereoOptions msp = WithDeformable();
      msp.deformable = variant != 0;
      msp.advanced_finest_deformable = variant == 2;
      // 4000 -> 2000 -> ... -> 62: seven rounds.
      const std::vector<Pass> schedule = BuildPassSchedule(pm, msp, 4000, 3000);
      ASSERT_EQ(schedule.size(), 7u * (geom ? 4 : 1));
      std::set<uint32_t> ids;
      int num_final = 0;
      for (size_t i = 0; i < schedule.size(); ++i) {
        const Pass& pass = schedule[i];
        EXPECT_TRUE(ids.insert(pass.id).second);
        num_final += pass.output == PassOutput::kFinal;
        EXPECT_EQ(pass.halvings, pass.num_rounds - 1 - pass.round);
        // A deformable pass takes the classes of the previous refine exactly
        // when that refine made them.
        const bool from_refine = i > 0 && schedule[i - 1].refine_classifies;
        if (pass.sweeps == PassSweeps::kDeformable) {
          EXPECT_EQ(pass.classify_after < 0, from_refine) << ToString(pass);
        } else {
          EXPECT_FALSE(from_refine) << ToString(pass);
        }
      }
      EXPECT_EQ(num_final, 1);
      EXPECT_EQ(schedule.back().output, PassOutput::kFinal);
    }
  }
}

}  // namespace
}  // namespace msp

// The README's main job on a small version of the bundled scene, through the
// installed-style commands: `colmap msp_stereo` (our dispatcher, handing
// stereo_fusion to the real COLMAP), `colmap stereo_fusion`, then the
// evaluator against the exact ground truth. A second run must resume: every
// image already has its outputs, so nothing is recomputed or rewritten.
//
// Three scenes (320x240, 6 views, seeds 1-3, each run with its seed) and the
// mean of their figures: one seed swings with the draws, the mean of three
// is steady enough for bounds a regression cannot pass. Measured with the
// default options (the mean of the three seeds):
//   maps within 5 % of valid pixels               0.845
//   fused accuracy at 2 % of the extent           0.947
//   F1 over >= 3-view surface at 2 %              0.906
//   textureless pixels within 1 %                 0.483 (0.454 without consensus planes)
//   pixels near a depth edge within 1 %           0.359
//   near an alike-colour edge within 1 %          0.331
//   sky pixels (ground truth empty) with a depth  0.034
// What the bounds catch (means, same scenes): segment planes off gives maps
// 0.758, F1 0.734, textureless 0.261 and depth on 83 % of the sky; the open
// sky rule off gives fused accuracy 0.898 and depth on 93 % of the sky.
// The deformable step (off by default, docs/method.md section 9) is not
// covered here: the tests of its parts are in tests/src/deformable.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "io/dense_map_io.h"
#include "tests/support/commands.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"
#include "tools/evaluate/evaluate_workspace.h"
#include "tools/scene/generate.h"

namespace msp {
namespace {

namespace fs = std::filesystem;

// Bounds on the means over the seeds, a little beyond what the default
// options reach (above): a bound moves only with a measured reason.
constexpr double kMinMapAccuracy5 = 0.80;         // valid pixels within 5 % depth
constexpr double kMinFusedAccuracyCoarse = 0.93;  // fused points within 2 % of the extent
constexpr double kMinF1MultiCoarse = 0.82;        // F1 over >= 3-view surface at 2 %
constexpr double kMinTexturelessWithin1 = 0.44;   // textureless ground-truth pixels within 1 %
constexpr double kMinNearEdgeWithin1 = 0.32;      // pixels near a true depth edge within 1 %
// Near depth edges between alike colours (the segmentation prior's target):
// ground-truth pixels within 1 %, and the region's share of all ground-truth
// pixels, which the scene's camouflaged objects keep measurable.
constexpr double kMinAlikeEdgeWithin1 = 0.29;
constexpr double kMinAlikeEdgeShare = 0.08;
// Pixels whose ground truth is empty (the sky through the window) that the
// maps give a depth: the outline's mixed pixels, nothing more.
constexpr double kMaxDepthWhereEmpty = 0.06;
constexpr int kNumViews = 6;
constexpr std::array<int, 3> kSeeds = {1, 2, 3};

int RunLogged(const std::string& command, const std::string& log) {
  return test::RunLogged("REAL_COLMAP=" + test::RealColmap() + " " + command, log);
}

const std::string kColmap = std::string(MSP_BIN_DIR) + "/colmap";

class EndToEndTest : public testing::Test {
 protected:
  static void TearDownTestSuite() { scratch_.reset(); }
  static void SetUpTestSuite() {
    scratch_ = std::make_unique<test::TempDir>();
    for (const int seed : kSeeds) {
      scene::GeneratorOptions options;
      options.output = Workspace(seed);
      options.seed = static_cast<uint64_t>(seed);
      options.rig.width = 320;
      options.rig.height = 240;
      options.rig.num_cameras = kNumViews;
      scene::GenerateScene(options);
    }
  }
  static std::string Workspace(int seed) { return *scratch_ / ("ws" + std::to_string(seed)); }

  // msp_stereo with the seed, checks of the maps, fusion, evaluation.
  static eval::EvaluationResult RunAndEvaluate(int seed) {
    const std::string ws = Workspace(seed);
    EXPECT_EQ(RunLogged(kColmap + " msp_stereo --workspace_path " + ws + " --random_seed " +
                            std::to_string(seed),
                        ws + "/stereo.log"),
              0)
        << test::ReadRaw(ws + "/stereo.log");
    for (int i = 0; i < kNumViews; ++i) {
      char name[32];
      std::snprintf(name, sizeof(name), "img_%03d.png", i);
      for (const char* type : {"photometric", "geometric"}) {
        const DenseMap depth =
            ReadDenseMap(ws + "/stereo/depth_maps/" + name + "." + type + ".bin");
        const DenseMap normal =
            ReadDenseMap(ws + "/stereo/normal_maps/" + name + "." + type + ".bin");
        EXPECT_EQ(depth.width, 320);
        EXPECT_EQ(normal.channels, 3);
        for (float v : depth.data) EXPECT_TRUE(std::isfinite(v) && v >= 0.0f);
        for (float v : normal.data) EXPECT_TRUE(std::isfinite(v));
      }
    }
    const std::string fused = ws + "/fused.ply";
    EXPECT_EQ(RunLogged(kColmap + " stereo_fusion --workspace_path " + ws +
                            " --input_type geometric --output_path " + fused,
                        ws + "/fusion.log"),
              0)
        << test::ReadRaw(ws + "/fusion.log");
    eval::EvaluationOptions options;
    options.workspace = ws;
    options.fused = fused;
    return eval::EvaluateWorkspace(options);
  }

  static std::unique_ptr<test::TempDir> scratch_;
};
std::unique_ptr<test::TempDir> EndToEndTest::scratch_;

// The means over the seeds of the bounded figures.
struct Figures {
  double map_accuracy5 = 0, fused_accuracy = 0, f1_multi = 0, textureless = 0, near_edge = 0,
         alike_edge = 0, alike_share = 0, depth_where_empty = 0;
};

TEST_F(EndToEndTest, MeanOfThreeSeedsThenResume) {
  ASSERT_TRUE(fs::exists(test::RealColmap()))
      << "colmap is not installed at " << test::RealColmap();
  Figures mean;
  for (const int seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const eval::EvaluationResult r = RunAndEvaluate(seed);
    ASSERT_FALSE(HasFailure());
    EXPECT_EQ(r.num_missing_maps, 0);
    ASSERT_TRUE(r.has_cloud);
    EXPECT_GT(r.average.empty.num_empty, 0) << "the scene has its sky";
    const eval::CloudThresholdMetrics& coarse = r.cloud.thresholds[1];
    const double n = static_cast<double>(kSeeds.size());
    mean.map_accuracy5 += r.average.all.accurate[1] / n;
    mean.fused_accuracy += coarse.accuracy / n;
    mean.f1_multi += coarse.f1_multi / n;
    mean.textureless += r.average.textureless.complete[0] / n;
    mean.near_edge += r.average.near_edge.complete[0] / n;
    mean.alike_edge += r.average.alike_edge.complete[0] / n;
    mean.alike_share +=
        static_cast<double>(r.average.alike_edge.num_gt) / std::max(1, r.average.all.num_gt) / n;
    mean.depth_where_empty += r.average.empty.with_depth_fraction / n;
  }
  RecordProperty("map_accuracy5_permille", static_cast<int>(1000 * mean.map_accuracy5));
  RecordProperty("fused_accuracy_coarse_permille", static_cast<int>(1000 * mean.fused_accuracy));
  RecordProperty("f1_multi_coarse_permille", static_cast<int>(1000 * mean.f1_multi));
  RecordProperty("textureless_within1_permille", static_cast<int>(1000 * mean.textureless));
  RecordProperty("near_edge_within1_permille", static_cast<int>(1000 * mean.near_edge));
  RecordProperty("alike_edge_within1_permille", static_cast<int>(1000 * mean.alike_edge));
  RecordProperty("depth_where_empty_permille", static_cast<int>(1000 * mean.depth_where_empty));
  EXPECT_GE(mean.map_accuracy5, kMinMapAccuracy5);
  EXPECT_GE(mean.fused_accuracy, kMinFusedAccuracyCoarse);
  EXPECT_GE(mean.f1_multi, kMinF1MultiCoarse);
  EXPECT_GE(mean.textureless, kMinTexturelessWithin1);
  EXPECT_GE(mean.near_edge, kMinNearEdgeWithin1);
  EXPECT_GE(mean.alike_edge, kMinAlikeEdgeWithin1);
  EXPECT_GE(mean.alike_share, kMinAlikeEdgeShare);
  EXPECT_LE(mean.depth_where_empty, kMaxDepthWhereEmpty);

  // Resume: a second run finds every output and leaves the files as they are.
  const std::string ws = Workspace(kSeeds[0]);
  const std::string before = test::ReadRaw(ws + "/stereo/depth_maps/img_000.png.geometric.bin");
  ASSERT_EQ(RunLogged(kColmap + " msp_stereo --workspace_path " + ws, ws + "/stereo2.log"), 0);
  EXPECT_NE(test::ReadRaw(ws + "/stereo2.log").find("nothing to do"), std::string::npos)
      << test::ReadRaw(ws + "/stereo2.log");
  EXPECT_EQ(test::ReadRaw(ws + "/stereo/depth_maps/img_000.png.geometric.bin"), before);
}

}  // namespace
}  // namespace msp

// The README's main job on a small version of the bundled scene, through the
// installed-style commands: `colmap msp_stereo` (our dispatcher, handing
// stereo_fusion to the real COLMAP), `colmap stereo_fusion`, then the
// evaluator against the exact ground truth. A second run must resume: every
// image already has its outputs, so nothing is recomputed or rewritten.
//
// The tolerances sit a little under what the default options reach on this
// scene (320x240, 6 views, seed 1), so that a regression fails. Measured:
// maps within 5 % 0.673 of valid pixels, fused accuracy at 2 % 0.770, F1 at
// 2 % 0.662, textureless pixels within 1 % 0.217, alike-edge pixels within
// 1 % 0.267, 9.7 % of the pixels alike-edge. The wall-coloured panel pulls
// the wall behind it off its plane, hence the low textureless figure. The
// fused figures swing with the seed on a scene this small (accuracy at 2 %
// 0.77, 0.88, 0.82 for seeds 1-3; 0.80, 0.89, 0.72 with the deformable step
// in every round): the test pins seed 1 and catches large regressions, not
// a point.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "colmap_ext/dense_map_io.h"
#include "integration/scene/generate.h"
#include "tests/support/commands.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"
#include "tools/evaluate_workspace.h"

namespace msp {
namespace {

namespace fs = std::filesystem;

// Tolerances, a little below what the default options reach here.
constexpr double kMinMapAccuracy5 = 0.57;         // valid pixels within 5 % depth
constexpr double kMinFusedAccuracyCoarse = 0.74;  // fused points within 2 % of the extent
constexpr double kMinF1MultiCoarse = 0.64;        // F1 over >= 3-view surface at 2 %
constexpr double kMinTexturelessWithin1 = 0.18;   // textureless ground-truth pixels within 1 %
// Near depth edges between alike colours (the segmentation prior's target):
// ground-truth pixels within 1 %, and the region's share of all ground-truth
// pixels, which the scene's camouflaged objects keep measurable.
constexpr double kMinAlikeEdgeWithin1 = 0.23;
constexpr double kMinAlikeEdgeShare = 0.08;
constexpr int kNumViews = 6;

int RunLogged(const std::string& command, const std::string& log) {
  return test::RunLogged("REAL_COLMAP=" + test::RealColmap() + " " + command, log);
}

class EndToEndTest : public testing::Test {
 protected:
  static void TearDownTestSuite() { scratch_.reset(); }
  static void SetUpTestSuite() {
    scratch_ = std::make_unique<test::TempDir>();
    ws_ = *scratch_ / "ws";
    scene::GeneratorOptions options;
    options.output = ws_;
    options.seed = 1;
    options.rig.width = 320;
    options.rig.height = 240;
    options.rig.num_cameras = kNumViews;
    scene::GenerateScene(options);
  }
  static std::unique_ptr<test::TempDir> scratch_;
  static std::string ws_;
};
std::unique_ptr<test::TempDir> EndToEndTest::scratch_;
std::string EndToEndTest::ws_;

const std::string kColmap = std::string(MSP_BIN_DIR) + "/colmap";

TEST_F(EndToEndTest, StereoFusionEvaluateThenResume) {
  ASSERT_TRUE(fs::exists(test::RealColmap()))
      << "colmap is not installed at " << test::RealColmap();
  ASSERT_EQ(RunLogged(kColmap + " msp_stereo --workspace_path " + ws_ + " --random_seed 1",
                      ws_ + "/stereo.log"),
            0)
      << test::ReadRaw(ws_ + "/stereo.log");
  for (int i = 0; i < kNumViews; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "img_%03d.png", i);
    for (const char* type : {"photometric", "geometric"}) {
      const DenseMap depth = ReadDenseMap(ws_ + "/stereo/depth_maps/" + name + "." + type + ".bin");
      const DenseMap normal =
          ReadDenseMap(ws_ + "/stereo/normal_maps/" + name + "." + type + ".bin");
      ASSERT_EQ(depth.width, 320);
      ASSERT_EQ(normal.channels, 3);
      for (float v : depth.data) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
      for (float v : normal.data) ASSERT_TRUE(std::isfinite(v));
    }
  }
  const std::string fused = ws_ + "/fused.ply";
  ASSERT_EQ(RunLogged(kColmap + " stereo_fusion --workspace_path " + ws_ +
                          " --input_type geometric --output_path " + fused,
                      ws_ + "/fusion.log"),
            0)
      << test::ReadRaw(ws_ + "/fusion.log");

  eval::EvaluationOptions options;
  options.workspace = ws_;
  options.fused = fused;
  const eval::EvaluationResult r = eval::EvaluateWorkspace(options);
  EXPECT_EQ(r.num_missing_maps, 0);
  const eval::CloudThresholdMetrics& coarse = r.cloud.thresholds[1];
  RecordProperty("map_accuracy5_permille", static_cast<int>(1000 * r.average.all.accurate[1]));
  RecordProperty("fused_accuracy_coarse_permille", static_cast<int>(1000 * coarse.accuracy));
  RecordProperty("f1_multi_coarse_permille", static_cast<int>(1000 * coarse.f1_multi));
  RecordProperty("textureless_within1_permille",
                 static_cast<int>(1000 * r.average.textureless.complete[0]));
  const double alike_share =
      static_cast<double>(r.average.alike_edge.num_gt) / std::max(1, r.average.all.num_gt);
  RecordProperty("alike_edge_within1_permille",
                 static_cast<int>(1000 * r.average.alike_edge.complete[0]));
  RecordProperty("alike_edge_share_permille", static_cast<int>(1000 * alike_share));
  EXPECT_GE(r.average.all.accurate[1], kMinMapAccuracy5);
  EXPECT_GE(coarse.accuracy, kMinFusedAccuracyCoarse);
  EXPECT_GE(coarse.f1_multi, kMinF1MultiCoarse);
  EXPECT_GE(r.average.textureless.complete[0], kMinTexturelessWithin1);
  EXPECT_GE(r.average.alike_edge.complete[0], kMinAlikeEdgeWithin1);
  EXPECT_GE(alike_share, kMinAlikeEdgeShare);

  // Resume: a second run finds every output and leaves the files as they are.
  const std::string before = test::ReadRaw(ws_ + "/stereo/depth_maps/img_000.png.geometric.bin");
  ASSERT_EQ(RunLogged(kColmap + " msp_stereo --workspace_path " + ws_, ws_ + "/stereo2.log"), 0);
  EXPECT_NE(test::ReadRaw(ws_ + "/stereo2.log").find("nothing to do"), std::string::npos)
      << test::ReadRaw(ws_ + "/stereo2.log");
  EXPECT_EQ(test::ReadRaw(ws_ + "/stereo/depth_maps/img_000.png.geometric.bin"), before);
}

}  // namespace
}  // namespace msp

// --MspStereo.write_previews end to end on a small bundled scene: msp_stereo
// at --PatchMatchStereo.max_image_size 160 (the ground truth is 320x240)
// writes, per image, the depth, normal and error pictures at the maps' size
// next to the prior preview; the error picture's classes are recomputed here
// from the .bin files and agree with the evaluator's figures; msp_evaluate
// names the pictures that exist; a resumed run leaves them as they are.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "io/colormaps.h"
#include "io/dense_map_io.h"
#include "io/ground_truth.h"
#include "io/map_previews.h"
#include "io/prior_previews.h"
#include "tests/support/commands.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"
#include "tools/evaluate/evaluate_workspace.h"
#include "tools/scene/generate.h"

namespace msp {
namespace {

using test::RunLogged;

namespace fs = std::filesystem;

constexpr int kSceneWidth = 320;
constexpr int kSceneHeight = 240;
constexpr int kMapWidth = 160;  // kStereoWithPreviews's --PatchMatchStereo.max_image_size
constexpr int kMapHeight = 120;
constexpr int kNumViews = 4;

const std::string kBin = MSP_BIN_DIR;
const std::string kStereoWithPreviews =
    kBin +
    "/msp_stereo --PatchMatchStereo.max_image_size 160 --MspStereo.write_previews 1 "
    "--MspStereo.deformable 1";  // the prior, whose edges the prior preview shows

// The bundled scene, as msp_make_scene renders it, in `ws`.
void MakeScene(const std::string& ws, uint64_t seed, int width, int height, int num_cameras) {
  scene::GeneratorOptions options;
  options.output = ws;
  options.seed = seed;
  options.rig.width = width;
  options.rig.height = height;
  options.rig.num_cameras = num_cameras;
  scene::GenerateScene(options);
}

Rgb PngPixel(const cv::Mat& bgr, int row, int col) {
  const cv::Vec3b p = bgr.at<cv::Vec3b>(row, col);
  return Rgb{p[2], p[1], p[0]};
}

// The class of map pixel (row, col), written out here rather than taken from
// ErrorPreview: ground-truth pixel round(i * gt_size / size), relative error
// against the scene's thresholds; a depth where the render's ground truth is
// empty (the sky) is its own class.
DepthErrorClass ExpectedClass(const DenseMap& depth, const DenseMap& gt, int row, int col,
                              const double thresholds[2]) {
  const int gt_row =
      std::min(gt.height - 1,
               static_cast<int>(std::lround(static_cast<double>(row) * gt.height / depth.height)));
  const int gt_col =
      std::min(gt.width - 1,
               static_cast<int>(std::lround(static_cast<double>(col) * gt.width / depth.width)));
  const float d_gt = gt.At(gt_row, gt_col);
  const float d = depth.At(row, col);
  const bool has_depth = std::isfinite(d) && d > 0.0f;
  if (!(d_gt > 0.0f))
    return has_depth ? DepthErrorClass::kOnEmpty : DepthErrorClass::kNoGroundTruth;
  if (!has_depth) return DepthErrorClass::kMissing;
  const double relative = std::abs(static_cast<double>(d) - d_gt) / d_gt;
  if (relative <= thresholds[0]) return DepthErrorClass::kAccurate;
  return relative <= thresholds[1] ? DepthErrorClass::kClose : DepthErrorClass::kWrong;
}

class PreviewsTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    scratch_ = std::make_unique<test::TempDir>();
    ws_ = *scratch_ / "ws";
    MakeScene(ws_, /*seed=*/2, kSceneWidth, kSceneHeight, kNumViews);
    stereo_exit_code_ =
        RunLogged(kStereoWithPreviews + " --workspace_path " + ws_, ws_ + "/stereo.log");
  }
  static void TearDownTestSuite() { scratch_.reset(); }

  void SetUp() override {
    ASSERT_EQ(stereo_exit_code_, 0) << test::ReadRaw(ws_ + "/stereo.log");
    info_ = ReadGroundTruthInfo(ws_ + "/ground_truth");
    ASSERT_EQ(info_.image_names.size(), static_cast<size_t>(kNumViews));
  }

  std::string MapPath(const char* folder, const std::string& name) const {
    return ws_ + "/stereo/" + folder + "/" + name + ".geometric.bin";
  }

  static std::unique_ptr<test::TempDir> scratch_;
  static std::string ws_;
  static int stereo_exit_code_;
  GroundTruthInfo info_;
};
std::unique_ptr<test::TempDir> PreviewsTest::scratch_;
std::string PreviewsTest::ws_;
int PreviewsTest::stereo_exit_code_ = -1;

TEST_F(PreviewsTest, PicturesMatchTheFinalMapsAndTheGroundTruth) {
  EXPECT_NE(test::ReadRaw(ws_ + "/stereo.log").find("Error previews against the ground truth"),
            std::string::npos);
  eval::EvaluationOptions options;
  options.workspace = ws_;
  const eval::EvaluationResult evaluation = eval::EvaluateWorkspace(options);
  for (size_t i = 0; i < info_.image_names.size(); ++i) {
    const std::string& name = info_.image_names[i];
    SCOPED_TRACE(name);
    const DenseMap depth = ReadDenseMap(MapPath("depth_maps", name));
    const DenseMap normal = ReadDenseMap(MapPath("normal_maps", name));
    const DenseMap gt = ReadDenseMap(info_.DepthMapPath(name));
    ASSERT_EQ(depth.width, kMapWidth);
    ASSERT_EQ(depth.height, kMapHeight);
    ASSERT_EQ(gt.width, kSceneWidth);  // so the error picture samples the ground truth
    const cv::Mat depth_png = cv::imread(MapPreviewPath(ws_, name, MapPreview::kDepth));
    const cv::Mat normal_png = cv::imread(MapPreviewPath(ws_, name, MapPreview::kNormal));
    const cv::Mat error_png = cv::imread(MapPreviewPath(ws_, name, MapPreview::kError));
    EXPECT_TRUE(fs::is_regular_file(PriorPreviewPath(ws_, name)));
    for (const cv::Mat* png : {&depth_png, &normal_png, &error_png}) {
      ASSERT_EQ(png->cols, kMapWidth);
      ASSERT_EQ(png->rows, kMapHeight);
    }
    std::map<DepthErrorClass, int> counts;
    int wrong_depth_black = 0, wrong_normal_black = 0, wrong_class = 0;
    for (int row = 0; row < kMapHeight; ++row) {
      for (int col = 0; col < kMapWidth; ++col) {
        const bool has_depth = depth.At(row, col) > 0.0f;
        wrong_depth_black += (PngPixel(depth_png, row, col) == Rgb{}) == has_depth;
        wrong_normal_black += (PngPixel(normal_png, row, col) == Rgb{}) == has_depth;
        const DepthErrorClass expected =
            ExpectedClass(depth, gt, row, col, info_.depth_relative_thresholds);
        wrong_class += PngPixel(error_png, row, col) != DepthErrorColor(expected);
        ++counts[expected];
      }
    }
    EXPECT_EQ(wrong_depth_black, 0) << "black exactly where the map has no depth";
    EXPECT_EQ(wrong_normal_black, 0);
    EXPECT_EQ(wrong_class, 0);
    // Green is the evaluator's cmp1 over ground-truth pixels and acc1 over
    // the valid ones.
    const int green = counts[DepthErrorClass::kAccurate];
    const int with_gt = kMapWidth * kMapHeight - counts[DepthErrorClass::kNoGroundTruth] -
                        counts[DepthErrorClass::kOnEmpty];
    const int valid = green + counts[DepthErrorClass::kClose] + counts[DepthErrorClass::kWrong];
    EXPECT_GT(green, 0);
    const eval::RegionMetrics& figures = evaluation.maps[i].all;
    ASSERT_EQ(figures.num_gt, with_gt);
    ASSERT_EQ(figures.num_valid, valid);
    EXPECT_DOUBLE_EQ(figures.complete[0], static_cast<double>(green) / with_gt);
    EXPECT_DOUBLE_EQ(figures.accurate[0], static_cast<double>(green) / valid);
    // Magenta is the evaluator's depth where the ground truth is empty.
    const eval::EmptyMetrics& empty = evaluation.maps[i].empty;
    EXPECT_EQ(empty.num_empty,
              counts[DepthErrorClass::kNoGroundTruth] + counts[DepthErrorClass::kOnEmpty]);
    EXPECT_EQ(empty.num_with_depth, counts[DepthErrorClass::kOnEmpty]);
  }
}

TEST_F(PreviewsTest, EvaluatorNamesThePicturesThatExistAndResumeKeepsThem) {
  const std::string before = test::ReadRaw(MapPreviewPath(ws_, "img_000.png", MapPreview::kDepth));
  ASSERT_EQ(RunLogged(kStereoWithPreviews + " --workspace_path " + ws_, ws_ + "/resume.log"), 0);
  EXPECT_NE(test::ReadRaw(ws_ + "/resume.log").find("nothing to do"), std::string::npos);
  EXPECT_EQ(test::ReadRaw(MapPreviewPath(ws_, "img_000.png", MapPreview::kDepth)), before);

  const std::string removed = MapPreviewPath(ws_, "img_001.png", MapPreview::kError);
  const std::string removed_bytes = test::ReadRaw(removed);
  ASSERT_TRUE(fs::remove(removed));
  const std::string evaluate =
      kBin + "/msp_evaluate --workspace " + ws_ + " --json " + ws_ + "/evaluation.json";
  ASSERT_EQ(RunLogged(evaluate, ws_ + "/evaluation.txt"), 0);
  const std::string text = test::ReadRaw(ws_ + "/evaluation.txt");
  const std::string json = test::ReadRaw(ws_ + "/evaluation.json");
  int named = 0;
  for (const std::string& name : info_.image_names) {
    const std::pair<std::string, std::string> previews[] = {
        {"depth", MapPreviewPath(ws_, name, MapPreview::kDepth)},
        {"normal", MapPreviewPath(ws_, name, MapPreview::kNormal)},
        {"error", MapPreviewPath(ws_, name, MapPreview::kError)},
        {"prior", PriorPreviewPath(ws_, name)}};
    for (const auto& preview : previews) {
      const bool in_text = text.find("  " + name + " " + preview.first + ": " + preview.second +
                                     "\n") != std::string::npos;
      const bool in_json =
          json.find("\"" + preview.first + "\": \"" + preview.second + "\"") != std::string::npos;
      const bool exists = preview.second != removed;
      EXPECT_EQ(in_text, exists) << preview.second << "\n" << text;
      EXPECT_EQ(in_json, exists) << preview.second;
      named += in_text;
    }
  }
  EXPECT_EQ(named, 4 * kNumViews - 1);
  test::WriteRaw(removed, removed_bytes);  // as it was, for the other tests
}

// Without the segmentation prior (here without deformable patches) the
// pictures of the maps are still written, and only the prior preview is not.
TEST(Previews, WrittenWithoutThePrior) {
  const test::TempDir scratch;
  const std::string ws = scratch / "ws";
  MakeScene(ws, /*seed=*/1, 96, 64, /*num_cameras=*/3);
  ASSERT_EQ(RunLogged(kBin + "/msp_stereo --workspace_path " + ws +
                          " --MspStereo.deformable 0 --MspStereo.write_previews 1",
                      ws + "/stereo.log"),
            0)
      << test::ReadRaw(ws + "/stereo.log");
  EXPECT_NE(test::ReadRaw(ws + "/stereo.log").find("writes no prior previews"), std::string::npos);
  for (const char* name : {"img_000.png", "img_001.png", "img_002.png"}) {
    for (MapPreview preview : {MapPreview::kDepth, MapPreview::kNormal, MapPreview::kError}) {
      const cv::Mat png = cv::imread(MapPreviewPath(ws, name, preview));
      EXPECT_EQ(png.cols, 96) << MapPreviewPath(ws, name, preview);
      EXPECT_EQ(png.rows, 64);
    }
    EXPECT_FALSE(fs::exists(PriorPreviewPath(ws, name)));
  }
}

}  // namespace
}  // namespace msp

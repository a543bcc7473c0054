#include "io/ground_truth.h"

#include <gtest/gtest.h>

#include "io/errors.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

TEST(GroundTruth, ReadsImagesExtentAndOptionalThresholds) {
  const test::TempDir dir;
  test::WriteRaw(dir / "images.txt", "a.png\n\n  b.png \n");
  test::WriteRaw(dir / "scene.json", "{\"extent\": 4.5, \"depth_relative_threshold_2\": 0.1}");
  const GroundTruthInfo info = ReadGroundTruthInfo(dir.path());
  EXPECT_EQ(info.image_names, (std::vector<std::string>{"a.png", "b.png"}));
  EXPECT_DOUBLE_EQ(info.extent, 4.5);
  EXPECT_DOUBLE_EQ(info.depth_relative_thresholds[0], 0.01);  // default kept
  EXPECT_DOUBLE_EQ(info.depth_relative_thresholds[1], 0.1);
  EXPECT_EQ(info.DepthMapPath("a.png"), dir.path() + "/depth_maps/a.png.bin");
}

// msp_import_rgbd's scene.json: absolute thresholds, where the depth came
// from and the rules of what was derived; the optional folders' presence.
TEST(GroundTruth, ReadsSensorProvenanceAndOptionalFolders) {
  const test::TempDir dir;
  test::WriteRaw(dir / "images.txt", "a.png\n");
  test::WriteRaw(
      dir / "scene.json",
      "{\"extent\": 2, \"absolute_threshold_metres_1\": 0.01,\n"
      " \"depth_source\": \"sensor, 1000 per metre\", \"normals_rule\" : \"plane fit\"}");
  test::WriteRaw(dir / "normal_maps/a.png.bin", "");
  const GroundTruthInfo info = ReadGroundTruthInfo(dir.path());
  EXPECT_DOUBLE_EQ(info.absolute_thresholds_m[0], 0.01);
  EXPECT_DOUBLE_EQ(info.absolute_thresholds_m[1], 0.05);  // default kept
  EXPECT_EQ(info.depth_source, "sensor, 1000 per metre");
  EXPECT_EQ(info.normals_rule, "plane fit");
  EXPECT_EQ(info.textureless_rule, "");
  EXPECT_TRUE(info.has_normals);
  EXPECT_FALSE(info.has_textureless);
}

TEST(GroundTruth, JsonStringNeedsAQuotedValue) {
  std::string value = "kept";
  EXPECT_FALSE(FindJsonString("{\"a\": 3}", "a", &value));
  EXPECT_FALSE(FindJsonString("{\"a\": \"open", "a", &value));
  EXPECT_FALSE(FindJsonString("{\"b\": \"x\"}", "a", &value));
  EXPECT_EQ(value, "kept");
  EXPECT_TRUE(FindJsonString("{\"a\":\"\"}", "a", &value));
  EXPECT_EQ(value, "");
}

TEST(GroundTruth, MissingExtentOrFileIsAnInputError) {
  const test::TempDir dir;
  EXPECT_THROW(ReadGroundTruthInfo(dir.path()), InputError);  // no images.txt
  test::WriteRaw(dir / "images.txt", "a.png\n");
  test::WriteRaw(dir / "scene.json", "{\"extent\": 0}");
  EXPECT_THROW(ReadGroundTruthInfo(dir.path()), InputError);
}

TEST(GroundTruth, DefaultFolderIsInsideTheWorkspace) {
  EXPECT_EQ(GroundTruthDir("ws", ""), "ws/ground_truth");
  EXPECT_EQ(GroundTruthDir("ws", "elsewhere"), "elsewhere");
}

// A map at half the ground truth's size compares pixel i with 2i; sizes that
// do not divide round to the nearest pixel and never leave the image.
TEST(GroundTruth, NearestIndexScalesPerAxisAndStaysInside) {
  EXPECT_EQ(NearestGroundTruthIndex(0, 320, 640), 0);
  EXPECT_EQ(NearestGroundTruthIndex(7, 320, 640), 14);
  EXPECT_EQ(NearestGroundTruthIndex(4, 5, 5), 4);
  EXPECT_EQ(NearestGroundTruthIndex(1, 3, 4), 1);       // 1.33 -> 1
  EXPECT_EQ(NearestGroundTruthIndex(2, 3, 4), 3);       // 2.67 -> 3
  EXPECT_EQ(NearestGroundTruthIndex(99, 100, 50), 49);  // 49.5 rounds up, clamped
  for (int i = 0; i < 213; ++i) EXPECT_LT(NearestGroundTruthIndex(i, 213, 480), 480);
}

}  // namespace
}  // namespace msp

#include "tools/evaluate/evaluate_report.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace msp {
namespace eval {
namespace {

// Two images: one with pictures, one without.
EvaluationResult TwoImages() {
  EvaluationResult r;
  r.info.dir = "ws/ground_truth";
  r.info.image_names = {"a.png", "b.png"};
  r.info.extent = 3.0;
  r.input_type = "geometric";
  r.maps.resize(2);
  r.maps[0].name = "a.png";
  r.maps[0].previews = {{"depth", "ws/stereo/prior_previews/a.png.depth.png"},
                        {"error", "ws/stereo/prior_previews/a.png.error.png"}};
  r.maps[1].name = "b.png";
  r.average = AverageMetrics(r.maps);
  return r;
}

// On exact renders the share of empty ground truth given a depth is a
// headline, overall and per image, in the text and the JSON.
TEST(EvaluateReport, DepthWhereTheGroundTruthIsEmptyIsAHeadline) {
  EvaluationResult r = TwoImages();
  r.maps[0].empty = {200, 10, 0.05};
  r.maps[1].empty = {200, 0, 0.0};
  r.average = AverageMetrics(r.maps);
  std::ostringstream out;
  PrintReport(r, out);
  const std::string text = out.str();
  EXPECT_NE(text.find("Depth where the ground truth is empty (sky, open background):   2.50 % of "
                      "400 pixels"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("a.png                  200        10    5.00"), std::string::npos) << text;
  const std::string json = ReportJson(r);
  EXPECT_NE(json.find("\"empty\": {\"num_empty\": 400, \"num_with_depth\": 10, "
                      "\"with_depth_fraction\": 0.025}"),
            std::string::npos)
      << json;
}

TEST(EvaluateReport, TextNamesEveryPreviewThatExists) {
  std::ostringstream out;
  PrintReport(TwoImages(), out);
  const std::string text = out.str();
  EXPECT_NE(text.find("  a.png depth: ws/stereo/prior_previews/a.png.depth.png\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  a.png error: ws/stereo/prior_previews/a.png.error.png\n"),
            std::string::npos);
  EXPECT_EQ(text.find("a.png normal"), std::string::npos);
  EXPECT_EQ(text.find("  b.png "), std::string::npos);
}

TEST(EvaluateReport, TextHasNoPreviewSectionWithoutPreviews) {
  EvaluationResult r = TwoImages();
  r.maps[0].previews.clear();
  std::ostringstream out;
  PrintReport(r, out);
  EXPECT_EQ(out.str().find("Previews"), std::string::npos) << out.str();
}

TEST(EvaluateReport, JsonHasAPreviewObjectPerImage) {
  const std::string json = ReportJson(TwoImages());
  EXPECT_NE(json.find("\"previews\": {\"depth\": \"ws/stereo/prior_previews/a.png.depth.png\", "
                      "\"error\": \"ws/stereo/prior_previews/a.png.error.png\"}"),
            std::string::npos)
      << json;
  const size_t b = json.find("\"name\": \"b.png\"");
  ASSERT_NE(b, std::string::npos);
  EXPECT_NE(json.find("\"previews\": {}", b), std::string::npos);
  const size_t average = json.find("\"average\":");
  ASSERT_NE(average, std::string::npos);
  EXPECT_EQ(json.find("\"previews\"", average), std::string::npos);  // figures only
}

TEST(EvaluateReport, EdgeRegionsInTextAndJson) {
  EvaluationResult r = TwoImages();
  r.maps[0].near_edge.num_gt = 17;
  r.maps[0].alike_edge.num_gt = 5;
  r.maps[0].edge_band_radius = 8;
  r.average = AverageMetrics(r.maps);
  std::ostringstream out;
  PrintReport(r, out);
  EXPECT_NE(out.str().find("pixels near a depth edge,"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("pixels near a depth edge between alike colours,"), std::string::npos);
  EXPECT_NE(out.str().find("within 8 ground-truth pixels"), std::string::npos);
  const std::string json = ReportJson(r);
  EXPECT_NE(json.find("\"edge_band_radius\": 8, \"all\": "), std::string::npos) << json;
  EXPECT_NE(json.find("\"near_edge\": {\"num_gt\": 17,"), std::string::npos);
  EXPECT_NE(json.find("\"alike_edge\": {\"num_gt\": 5,"), std::string::npos);
  const size_t average = json.find("\"average\":");
  ASSERT_NE(average, std::string::npos);
  EXPECT_NE(json.find("\"near_edge\": {\"num_gt\": 17,", average), std::string::npos);
  EXPECT_NE(json.find("\"alike_edge\": {\"num_gt\": 5,", average), std::string::npos);
}

TEST(EvaluateReport, AbsoluteThresholdsInTextAndJson) {
  EvaluationResult r = TwoImages();
  r.maps[0].all.complete_abs[0] = 0.25;
  r.maps[0].all.accurate_abs[1] = 0.75;
  r.average = AverageMetrics(r.maps);
  r.has_cloud = true;
  r.cloud.num_points = 10;
  r.cloud.num_judged = 8;
  CloudThresholdMetrics t;
  t.metres = 0.05;
  t.absolute = true;
  r.cloud.thresholds = {t};
  std::ostringstream out;
  PrintReport(r, out);
  EXPECT_NE(out.str().find("0.02 m / 0.05 m absolute (cmpA1, cmpA2, accA1, accA2)"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("10 points, 8 judged"), std::string::npos);
  EXPECT_NE(out.str().find("\n0.0500 m "), std::string::npos);
  const std::string json = ReportJson(r);
  EXPECT_NE(json.find("\"absolute_thresholds_metres\": [0.02, 0.05]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"complete_abs_1\": 0.25,"), std::string::npos);
  EXPECT_NE(json.find("\"accurate_abs_2\": 0.75,"), std::string::npos);
  EXPECT_NE(json.find("\"num_judged\": 8"), std::string::npos);
  EXPECT_NE(json.find("\"off_textureless\": null"), std::string::npos);
  EXPECT_NE(json.find("\"metres\": 0.05, \"absolute\": true"), std::string::npos);
}

// The accuracy of the points off textureless surfaces (surfaces made up where
// the images have no evidence show there), in the text and the JSON.
TEST(EvaluateReport, AccuracyOffTexturelessSurfaces) {
  EvaluationResult r = TwoImages();
  r.has_cloud = true;
  CloudThresholdMetrics t;
  t.fraction = 0.005;
  r.cloud.thresholds = {t};
  r.has_cloud_off_textureless = true;
  r.cloud_off_textureless.num_judged = 6;
  t.accuracy = 0.5;
  r.cloud_off_textureless.thresholds = {t};
  std::ostringstream out;
  PrintReport(r, out);
  EXPECT_NE(out.str().find("Accuracy off textureless surfaces (6 points on textured surfaces or "
                           "on none, as in the sky):  50.00 %"),
            std::string::npos)
      << out.str();
  EXPECT_NE(ReportJson(r).find("\"off_textureless\": {\"num_judged\": 6, \"accuracy\": [0.5]}"),
            std::string::npos)
      << ReportJson(r);
}

// Sensor ground truth states its source and rules; without textureless masks
// the textureless / textured tables are left out (null in the JSON), without
// normals the normal error reads n/a.
TEST(EvaluateReport, SaysWhatTheGroundTruthLacks) {
  EvaluationResult r = TwoImages();
  r.info.depth_source = "sensor";
  r.info.has_textureless = false;
  r.info.has_normals = false;
  std::ostringstream out;
  PrintReport(r, out);
  const std::string text = out.str();
  EXPECT_NE(text.find("Ground-truth depth: sensor; pixels without a measurement (0) count "
                      "neither way"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("No textureless masks"), std::string::npos);
  EXPECT_NE(text.find("No ground-truth normals"), std::string::npos);
  EXPECT_EQ(text.find("textureless pixels only"), std::string::npos);
  EXPECT_NE(text.find("n/a\n"), std::string::npos);
  EXPECT_EQ(text.find("ground truth is empty"), std::string::npos);
  const std::string json = ReportJson(r);
  EXPECT_NE(json.find("\"textureless\": null, \"textured\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"empty\": null"), std::string::npos);
  EXPECT_NE(json.find("\"has_normals\": false"), std::string::npos);
}

}  // namespace
}  // namespace eval
}  // namespace msp

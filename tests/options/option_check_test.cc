#include "options/option_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tests/support/error_message.h"

namespace msp {
namespace {

StereoCommandOptions Valid() {
  StereoCommandOptions options;
  options.workspace_path = "ws";
  return options;
}

// The message of the OptionError thrown by Check, or "" if none.
std::string CheckError(const StereoCommandOptions& options) {
  return test::ErrorMessage<OptionError>([&] { CheckStereoCommandOptions(options); });
}

// The option an "invalid value V for --<name>: ..." message names.
std::string NamedOption(const std::string& message) {
  const std::string marker = " for --";
  const size_t begin = message.find(marker);
  if (begin == std::string::npos) return "";
  const size_t end = message.find(':', begin);
  return message.substr(begin + marker.size(), end - begin - marker.size());
}

// Whether the parser accepts `name` (so a message names an option a user can set).
bool IsRegistered(const std::string& name) {
  const std::vector<std::string> names = StereoCommandOptionNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

struct BadCase {
  std::string option;  // as named in the message, without "--"
  std::string value;   // as printed in the message
  std::string range;   // a piece of the allowed range in the message
  std::function<void(StereoCommandOptions*)> apply;
};

TEST(OptionCheck, DefaultsAreValid) { EXPECT_EQ(CheckError(Valid()), ""); }

TEST(OptionCheck, EveryOutOfRangeValueNamesOptionValueAndRange) {
  const std::vector<BadCase> cases = {
      {"PatchMatchStereo.window_radius", "0", "[1, 20]",
       [](auto* o) { o->patch_match.window_radius = 0; }},
      {"PatchMatchStereo.window_radius", "21", "[1, 20]",
       [](auto* o) { o->patch_match.window_radius = 21; }},
      {"PatchMatchStereo.window_radius", "32", "kMaxWindowRadius",
       [](auto* o) { o->patch_match.window_radius = 32; }},
      {"PatchMatchStereo.window_step", "0", "[1, 2]",
       [](auto* o) { o->patch_match.window_step = 0; }},
      {"PatchMatchStereo.window_step", "3", "[1, 2]",
       [](auto* o) { o->patch_match.window_step = 3; }},
      {"PatchMatchStereo.depth_min", "-0.5", "-1 (automatic, with --PatchMatchStereo.depth_max -1)",
       [](auto* o) {
         o->patch_match.depth_min = -0.5;
         o->patch_match.depth_max = 2;
       }},
      {"PatchMatchStereo.depth_min", "-1", "[0, --PatchMatchStereo.depth_max = 5]",
       [](auto* o) { o->patch_match.depth_max = 5; }},
      {"PatchMatchStereo.depth_max", "1", ">= --PatchMatchStereo.depth_min = 2",
       [](auto* o) {
         o->patch_match.depth_min = 2;
         o->patch_match.depth_max = 1;
       }},
      {"PatchMatchStereo.depth_max", "-1", ">= --PatchMatchStereo.depth_min = 2",
       [](auto* o) { o->patch_match.depth_min = 2; }},
      {"PatchMatchStereo.sigma_color", "0", "> 0", [](auto* o) { o->patch_match.sigma_color = 0; }},
      {"PatchMatchStereo.num_samples", "0", "> 0", [](auto* o) { o->patch_match.num_samples = 0; }},
      {"PatchMatchStereo.ncc_sigma", "-1", "> 0", [](auto* o) { o->patch_match.ncc_sigma = -1; }},
      {"PatchMatchStereo.min_triangulation_angle", "180", "[0, 180)",
       [](auto* o) { o->patch_match.min_triangulation_angle = 180; }},
      {"PatchMatchStereo.min_triangulation_angle", "-1", "[0, 180)",
       [](auto* o) { o->patch_match.min_triangulation_angle = -1; }},
      {"PatchMatchStereo.incident_angle_sigma", "0", "> 0",
       [](auto* o) { o->patch_match.incident_angle_sigma = 0; }},
      {"PatchMatchStereo.num_iterations", "0", "> 0",
       [](auto* o) { o->patch_match.num_iterations = 0; }},
      {"PatchMatchStereo.geom_consistency_regularizer", "-0.1", ">= 0",
       [](auto* o) { o->patch_match.geom_consistency_regularizer = -0.1; }},
      {"PatchMatchStereo.geom_consistency_max_cost", "-1", ">= 0",
       [](auto* o) { o->patch_match.geom_consistency_max_cost = -1; }},
      {"PatchMatchStereo.filter_min_ncc", "1.5", "[-1, 1]",
       [](auto* o) { o->patch_match.filter_min_ncc = 1.5; }},
      {"PatchMatchStereo.filter_min_ncc", "-2", "[-1, 1]",
       [](auto* o) { o->patch_match.filter_min_ncc = -2; }},
      {"PatchMatchStereo.filter_min_triangulation_angle", "181", "[0, 180]",
       [](auto* o) { o->patch_match.filter_min_triangulation_angle = 181; }},
      {"PatchMatchStereo.filter_min_triangulation_angle", "-1", "[0, 180]",
       [](auto* o) { o->patch_match.filter_min_triangulation_angle = -1; }},
      {"PatchMatchStereo.filter_min_num_consistent", "-1", ">= 0",
       [](auto* o) { o->patch_match.filter_min_num_consistent = -1; }},
      {"PatchMatchStereo.filter_geom_consistency_max_cost", "-1", ">= 0",
       [](auto* o) { o->patch_match.filter_geom_consistency_max_cost = -1; }},
      {"PatchMatchStereo.cache_size", "0", "> 0", [](auto* o) { o->patch_match.cache_size = 0; }},
      {"MspStereo.backend", "`opencl`", "{auto, cpu, cuda}",
       [](auto* o) { o->msp.backend = "opencl"; }},
      {"random_seed", "-3", ">= 0", [](auto* o) { o->random_seed = -3; }},
      {"MspStereo.window_step", "3", "[1, 2]", [](auto* o) { o->msp.window_step = 3; }},
      {"MspStereo.advanced_reliable_max_cost", "2.5", "[0, 2]",
       [](auto* o) { o->msp.advanced_reliable_max_cost = 2.5; }},
      {"MspStereo.advanced_reliable_single_cost", "-0.1", "[0, 2]",
       [](auto* o) { o->msp.advanced_reliable_single_cost = -0.1; }},
      {"MspStereo.advanced_reliable_min_spread", "3", "[0, 2]",
       [](auto* o) { o->msp.advanced_reliable_min_spread = 3; }},
      {"MspStereo.advanced_restoring_image_size", "-1", ">= 0",
       [](auto* o) { o->msp.advanced_restoring_image_size = -1; }},
      {"MspStereo.geom_consistency_depth_weight", "-0.2", ">= 0",
       [](auto* o) { o->msp.geom_consistency_depth_weight = -0.2; }},
      {"MspStereo.advanced_anchor_max_distance", "1", "[2, 65536]",
       [](auto* o) { o->msp.advanced_anchor_max_distance = 1; }},
      {"MspStereo.advanced_equidistribution_iterations", "0", "[1, 3]",
       [](auto* o) { o->msp.advanced_equidistribution_iterations = 0; }},
      {"MspStereo.advanced_equidistribution_iterations", "4", "[1, 3]",
       [](auto* o) { o->msp.advanced_equidistribution_iterations = 4; }},
      {"MspStereo.advanced_coarsest_image_size", "10", "[64, ",
       [](auto* o) { o->msp.advanced_coarsest_image_size = 10; }},
      {"workspace_format", "`CMP-MVS`", "{COLMAP, PMVS}",
       [](auto* o) { o->workspace_format = "CMP-MVS"; }},
  };
  for (const BadCase& c : cases) {
    StereoCommandOptions options = Valid();
    c.apply(&options);
    const std::string error = CheckError(options);
    EXPECT_NE(error.find("--" + c.option + ":"), std::string::npos) << c.option << ": " << error;
    EXPECT_TRUE(IsRegistered(NamedOption(error))) << error;
    EXPECT_NE(error.find("invalid value " + c.value + " "), std::string::npos) << error;
    EXPECT_NE(error.find(c.range), std::string::npos) << error;
  }
}

TEST(OptionCheck, BoundaryValuesAreValid) {
  StereoCommandOptions o = Valid();
  o.patch_match.window_radius = kMaxWindowRadius;
  o.patch_match.window_step = 2;
  o.patch_match.depth_min = 0.0;
  o.patch_match.depth_max = 0.0;
  o.patch_match.min_triangulation_angle = 0.0;
  o.patch_match.geom_consistency_regularizer = 0.0;
  o.patch_match.geom_consistency_max_cost = 0.0;
  o.patch_match.filter_min_ncc = -1.0;
  o.patch_match.filter_min_triangulation_angle = 180.0;
  o.patch_match.filter_min_num_consistent = 0;
  o.patch_match.filter_geom_consistency_max_cost = 0.0;
  o.patch_match.sigma_spatial = -5.0;  // <= 0 means window_radius; no rule in COLMAP
  o.msp.backend = "cuda";
  o.workspace_format = "PMVS";
  EXPECT_EQ(CheckError(o), "");
  o.patch_match.window_radius = 1;
  o.patch_match.filter_min_ncc = 1.0;
  EXPECT_EQ(CheckError(o), "");
}

TEST(OptionCheck, NanIsRejected) {
  StereoCommandOptions o = Valid();
  o.patch_match.sigma_color = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(CheckError(o).find("--PatchMatchStereo.sigma_color"), std::string::npos);
}

TEST(OptionCheck, MessageNamesTheOptionOfTheField) {
  // Option names in messages are spelt from the fields, with the section.
  StereoCommandOptions o = Valid();
  o.msp.window_step = 0;
  EXPECT_EQ(NamedOption(CheckError(o)), "MspStereo.window_step");
  o = Valid();
  o.patch_match.window_step = 0;
  EXPECT_EQ(NamedOption(CheckError(o)), "PatchMatchStereo.window_step");
  o = Valid();
  o.workspace_format = "X";
  EXPECT_EQ(NamedOption(CheckError(o)), "workspace_format");
}

TEST(OptionCheck, WorkspacePathRequired) {
  StereoCommandOptions o;
  EXPECT_NE(CheckError(o).find("--workspace_path"), std::string::npos);
}

TEST(OptionCheck, SegmentationPriorRules) {
  const std::vector<BadCase> cases = {
      {"MspStereo.advanced_num_mask_levels", "0", "[1, 32]",
       [](auto* o) { o->msp.advanced_num_mask_levels = 0; }},
      {"MspStereo.advanced_num_mask_levels", "33", "kMaxLabelLayers",
       [](auto* o) { o->msp.advanced_num_mask_levels = 33; }},
      {"MspStereo.advanced_num_mask_levels", "32", "[1, 31] with --MspStereo.geometry_layers",
       [](auto* o) { o->msp.advanced_num_mask_levels = 32; }},
      {"MspStereo.segmenter", "`fast`", "one of {opencv, embedded}",
       [](auto* o) { o->msp.segmenter = "fast"; }},
      {"MspStereo.advanced_crf_alpha", "0", "> 0", [](auto* o) { o->msp.advanced_crf_alpha = 0; }},
      {"MspStereo.advanced_crf_beta", "-1", "> 0", [](auto* o) { o->msp.advanced_crf_beta = -1; }},
      {"MspStereo.advanced_crf_unary_confidence", "1", "(0, 1)",
       [](auto* o) { o->msp.advanced_crf_unary_confidence = 1; }},
      {"MspStereo.advanced_crf_iterations", "0", "> 0",
       [](auto* o) { o->msp.advanced_crf_iterations = 0; }},
      {"MspStereo.advanced_dbscan_eta", "32", "[0, 31]",
       [](auto* o) { o->msp.advanced_dbscan_eta = 32; }},
      {"MspStereo.advanced_dbscan_gamma", "-1", ">= 0",
       [](auto* o) { o->msp.advanced_dbscan_gamma = -1; }},
      {"MspStereo.advanced_sampling_solutions", "0", "[1, 32]",
       [](auto* o) { o->msp.advanced_sampling_solutions = 0; }},
      {"MspStereo.advanced_disparity_samples", "9", "[1, 7]",
       [](auto* o) { o->msp.advanced_disparity_samples = 9; }},
      {"MspStereo.advanced_disparity_samples", "4", "odd",
       [](auto* o) { o->msp.advanced_disparity_samples = 4; }},
      {"MspStereo.advanced_disparity_step", "0", "> 0",
       [](auto* o) { o->msp.advanced_disparity_step = 0; }},
      {"MspStereo.advanced_variance_weight", "-1", ">= 0",
       [](auto* o) { o->msp.advanced_variance_weight = -1; }},
  };
  for (const BadCase& c : cases) {
    StereoCommandOptions o = Valid();
    c.apply(&o);
    const std::string message = CheckError(o);
    EXPECT_NE(message.find("--" + c.option), std::string::npos) << message;
    EXPECT_TRUE(IsRegistered(NamedOption(message))) << message;
    EXPECT_NE(message.find(c.value), std::string::npos) << message;
    EXPECT_NE(message.find(c.range), std::string::npos) << message;
  }
}

TEST(OptionCheck, GeometryLayersOffLeaveAllLayersToColourAndBothSegmentersAreValid) {
  StereoCommandOptions o = Valid();
  o.msp.geometry_layers = false;
  o.msp.advanced_num_mask_levels = 32;
  EXPECT_EQ(CheckError(o), "");
  for (const char* segmenter : {"opencv", "embedded"}) {
    o = Valid();
    o.msp.segmenter = segmenter;
    EXPECT_EQ(CheckError(o), "") << segmenter;
  }
}

}  // namespace
}  // namespace msp

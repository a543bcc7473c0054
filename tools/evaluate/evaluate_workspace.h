// Evaluates a workspace's depth / normal maps and optionally a fused point
// cloud against the ground truth written by msp_make_scene.
#pragma once

#include <string>
#include <vector>

#include "io/ground_truth.h"
#include "tools/evaluate/evaluate_cloud.h"
#include "tools/evaluate/evaluate_depth.h"

namespace msp {
namespace eval {

struct EvaluationOptions {
  std::string workspace;
  std::string ground_truth;              // default <workspace>/ground_truth
  std::string input_type = "geometric";  // suffix of the maps: geometric | photometric
  std::string fused;                     // fused.ply to evaluate; empty: none
  bool evaluate_maps = true;
};

struct EvaluationResult {
  GroundTruthInfo info;
  std::string input_type;
  std::vector<DepthMapMetrics> maps;  // ground-truth image order
  DepthMapMetrics average;
  int num_missing_maps = 0;
  bool has_cloud = false;
  std::string fused;
  CloudMetrics cloud;
  // The cloud's accuracy over the points that are not on a textureless
  // surface (OnTexturelessSurface: on textured ones, or on none, as in the
  // sky); its completeness figures are those of `cloud`. Needs textureless
  // masks.
  bool has_cloud_off_textureless = false;
  CloudMetrics cloud_off_textureless;
};

// Throws InputError on unreadable ground truth or point clouds. Missing maps
// are reported (missing = true), not fatal: a method may skip images.
EvaluationResult EvaluateWorkspace(const EvaluationOptions& options);

}  // namespace eval
}  // namespace msp

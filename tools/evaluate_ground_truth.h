// What the evaluator needs from a ground_truth/ folder written by
// msp_make_scene: the image list, the scene extent and the default thresholds.
#pragma once

#include <string>
#include <vector>

namespace msp {
namespace eval {

struct GroundTruthInfo {
  std::string dir;
  std::vector<std::string> image_names;  // images.txt, in model order
  double extent = 0.0;                   // bounding-box diagonal of the visible surface (m)
  double cloud_threshold_fractions[2] = {0.005, 0.02};
  double depth_relative_thresholds[2] = {0.01, 0.05};
  int min_views_for_completeness = 3;

  std::string DepthMapPath(const std::string& name) const;     // depth_maps/<name>.bin
  std::string NormalMapPath(const std::string& name) const;    // normal_maps/<name>.bin
  std::string TexturelessPath(const std::string& name) const;  // textureless/<name>.png
  std::string SurfacePath() const;                             // surface.ply
};

// Reads <dir>/images.txt and <dir>/scene.json. Throws InputError naming the
// file when one is missing or lacks a required key.
GroundTruthInfo ReadGroundTruthInfo(const std::string& dir);

// The number stored under "key" in a flat JSON text, or false. Enough for the
// generator's scene.json (no nesting of the keys looked up).
bool FindJsonNumber(const std::string& json, const std::string& key, double* value);

}  // namespace eval
}  // namespace msp

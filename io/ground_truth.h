// The ground_truth/ folder that msp_make_scene writes next to a workspace:
// the image list, the scene extent, the evaluation thresholds and the paths of
// the per-image maps. Read by the evaluator, by msp_write_gt_maps and by
// msp_stereo's error previews, so that all three agree on the layout.
#pragma once

#include <string>
#include <vector>

namespace msp {

struct GroundTruthInfo {
  std::string dir;
  std::vector<std::string> image_names;  // images.txt, in model order
  double extent = 0.0;                   // bounding-box diagonal of the visible surface (m)
  double cloud_threshold_fractions[2] = {0.005, 0.02};
  double depth_relative_thresholds[2] = {0.01, 0.05};
  // Absolute thresholds (metres) of depth maps and fused clouds, beside the
  // relative ones: 2 cm and 5 cm, the figures of sensor benchmarks, which say
  // what a user of a room-sized capture sees; scene.json's
  // "absolute_threshold_metres_1/2" may change them.
  double absolute_thresholds_m[2] = {0.02, 0.05};
  int min_views_for_completeness = 3;
  // How the ground truth was made, said beside its figures: empty for the
  // bundled scene's exact renders; msp_import_rgbd's sensor ground truth
  // states its source and the rules of what it derived (scene.json's
  // "depth_source", "normals_rule", "textureless_rule").
  std::string depth_source;
  std::string normals_rule;
  std::string textureless_rule;
  // Whether the optional folders exist: without normal_maps/ there are no
  // normal errors, without textureless/ no textureless / textured split.
  bool has_normals = true;
  bool has_textureless = true;

  // What a ground-truth depth of 0 means. In exact renders (no depth_source)
  // nothing is there: sky, open background, and a map's depth there is a
  // surface made up. From a sensor it means no measurement: nothing is known.
  bool ZeroDepthIsEmpty() const { return depth_source.empty(); }

  std::string DepthMapPath(const std::string& name) const;     // depth_maps/<name>.bin
  std::string NormalMapPath(const std::string& name) const;    // normal_maps/<name>.bin
  std::string TexturelessPath(const std::string& name) const;  // textureless/<name>.png
  std::string SurfacePath() const;                             // surface.ply
};

// `dir`, or <workspace>/ground_truth when `dir` is empty.
std::string GroundTruthDir(const std::string& workspace, const std::string& dir);

// Reads <dir>/images.txt and <dir>/scene.json. Throws InputError naming the
// file when one is missing or lacks a required key.
GroundTruthInfo ReadGroundTruthInfo(const std::string& dir);

// The number stored under "key" in a flat JSON text, or false. Enough for the
// generator's scene.json (no nesting of the keys looked up).
bool FindJsonNumber(const std::string& json, const std::string& key, double* value);
// The string stored under "key" (no escapes inside), or false.
bool FindJsonString(const std::string& json, const std::string& key, std::string* value);

// A map may be smaller than the ground truth (--PatchMatchStereo.max_image_size):
// pixel `index` of an axis of `size` pixels is compared with ground-truth
// pixel round(index * gt_size / size), the nearest one under the per-axis
// intrinsics scaling that COLMAP's fusion uses.
int NearestGroundTruthIndex(int index, int size, int gt_size);

}  // namespace msp

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
  int min_views_for_completeness = 3;

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

// A map may be smaller than the ground truth (--PatchMatchStereo.max_image_size):
// pixel `index` of an axis of `size` pixels is compared with ground-truth
// pixel round(index * gt_size / size), the nearest one under the per-axis
// intrinsics scaling that COLMAP's fusion uses.
int NearestGroundTruthIndex(int index, int size, int gt_size);

}  // namespace msp

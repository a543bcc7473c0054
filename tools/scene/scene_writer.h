// Writes the generated scene as a COLMAP dense workspace (the layout of
// `colmap image_undistorter --output_type COLMAP`) plus a ground_truth/ folder.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/sparse_model.h"
#include "tools/scene/camera_rig.h"
#include "tools/scene/renderer.h"
#include "tools/scene/surface_ids.h"
#include "tools/scene/surface_sample.h"

namespace msp {
namespace scene {

// Defaults of the evaluator, stored in scene.json: point-cloud distance
// thresholds as fractions of the extent (bounding-box diagonal of the
// visible surface) and the relative depth-error thresholds of depth maps.
constexpr double kCloudThresholdFractions[2] = {0.005, 0.02};
constexpr double kDepthRelativeThresholds[2] = {0.01, 0.05};
// COLMAP's default fusion needs a surface seen by >= 3 views to fuse it, so
// completeness is also reported over those samples.
constexpr int kMinViewsForCompleteness = 3;
// `__auto__, N` in patch-match.cfg: image_undistorter's default.
constexpr int kNumPatchMatchSources = 20;

// images/, sparse/, stereo/{patch-match,fusion}.cfg, run-colmap-*.sh.
void WriteColmapWorkspace(const std::string& dir, const SparseModel& model,
                          const std::vector<RenderedView>& rendered);

// scene.json: the extent and bounding box of the surface sample, the
// evaluator's thresholds and every camera, after `header`'s entries (key and
// a value already in JSON form, e.g. {"seed", "1"}), which say where the
// ground truth came from.
std::string GroundTruthJson(const std::vector<PinholeView>& views, const SurfaceSample& sample,
                            const std::vector<std::pair<std::string, std::string>>& header);

// ground_truth/{depth_maps,normal_maps}/<name>.bin, textureless/<name>.png,
// surface.ply, images.txt (one name per line) and scene.json (the given text,
// GroundTruthJson). `rendered` gives each view's depth, normal and
// textureless maps (its image is not written here).
void WriteGroundTruth(const std::string& dir, const std::vector<PinholeView>& views,
                      const std::vector<RenderedView>& rendered, const SurfaceSample& sample,
                      const std::string& scene_json);

// masks/<name>.<level>.png, the layout of the segmentation prior's mask
// layers (io/mask_layers.h): `masks[i]` of views[i], one 16-bit PNG a level.
void WriteIdealMasks(const std::string& dir, const std::vector<PinholeView>& views,
                     const std::vector<IdealMasks>& masks);

}  // namespace scene
}  // namespace msp

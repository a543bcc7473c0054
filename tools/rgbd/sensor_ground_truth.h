// Writes <workspace>/ground_truth for a sensor capture in the layout
// msp_evaluate reads (io/ground_truth.h): the measured depth as the
// depth maps (0 = no measurement), normals and textureless masks derived by
// the rules of depth_normals.h and textureless_mask.h, the surface sample of
// measured_surface.h, images.txt and scene.json, which states the depth's
// source and both rules so the evaluator can print them.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "base/dense_map.h"
#include "tools/scene/camera_rig.h"

namespace msp {
namespace rgbd {

struct SensorFrame {
  scene::PinholeView view;  // the true rays: integer index = image point
  cv::Mat image;            // CV_8UC3 BGR, as the workspace holds it
  DenseMap depth;           // metres, 0 = no measurement
};

struct SensorGroundTruthSummary {
  int num_surface_samples = 0;
  double extent = 0.0;
  double measured_fraction = 0.0;  // of all pixels, over the frames
};

// `header` goes first in scene.json (key, JSON value): where the depth came
// from and how it was imported.
SensorGroundTruthSummary WriteSensorGroundTruth(
    const std::string& workspace, const std::vector<SensorFrame>& frames,
    const std::vector<std::pair<std::string, std::string>>& header);

// The rules as scene.json states them ("normals_rule", "textureless_rule").
std::string NormalsRule();
std::string TexturelessRule();

}  // namespace rgbd
}  // namespace msp

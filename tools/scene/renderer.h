// Renders one view of a Scene: the noisy anti-aliased colour image a camera
// would record, and the exact ground truth at the same pixels.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "base/dense_map.h"
#include "tools/scene/camera_rig.h"
#include "tools/scene/scene.h"

namespace msp {
namespace scene {

struct RenderedView {
  cv::Mat image;        // CV_8UC3, BGR (OpenCV order)
  DenseMap depth;       // 1 channel: camera z of the surface at each pixel
  DenseMap normal;      // 3 channels: unit camera-frame normal facing the camera
  cv::Mat textureless;  // CV_8UC1: 255 where the surface material is textureless
};

// Standard deviation of the simulated sensor noise, in 8-bit grey levels.
constexpr double kImageNoiseSigma = 1.0;

// view_index keys the noise of this view: the same (seed, view_index) always
// gives the same image.
RenderedView RenderView(const Scene& scene, const PinholeView& view, int view_index, uint64_t seed);

// Casts the ray through (col, row): the ground-truth depth and normal.
// Returns false when the ray leaves the scene (never inside the closed room).
bool GroundTruthAt(const Scene& scene, const PinholeView& view, double col, double row, Hit* hit,
                   double* depth, Eigen::Vector3d* camera_normal);

// True when the world point X (on a scene surface) projects into the view and
// is not hidden by another surface; fills its image point.
bool IsVisible(const Scene& scene, const PinholeView& view, const Eigen::Vector3d& X,
               double* col = nullptr, double* row = nullptr);

}  // namespace scene
}  // namespace msp

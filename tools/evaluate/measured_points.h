// Which reconstructed points the ground truth can judge. Sensor depth has no
// measurement on dark, shiny or distant surfaces (value 0), so a fused point
// there is no evidence either way: counting it as wrong would punish a method
// for reconstructing what the sensor missed, counting it as right would
// reward anything. The rule: a point is judged when at least one
// ground-truth view has a measurement where the point projects (in front of
// the camera, inside the image, ground-truth depth > 0 at the nearest pixel).
// For rendered ground truth, whose 0 means nothing is there (sky), every
// point any view sees is judged (`zero_is_empty`): a point in the sky is
// judged, and far from every surface.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "base/dense_map.h"
#include "core/math/camera.h"

namespace msp {
namespace eval {

struct MeasuredView {
  core::Camera camera;  // at the ground truth's size, COLMAP MVS pixel convention
  DenseMap depth;       // ground-truth depth, 0 = no measurement or nothing there
  cv::Mat textureless;  // CV_8UC1 at the depth's size, non-zero inside; may be empty
};

// One flag per point: 1 = judged.
std::vector<uint8_t> MeasuredPoints(const std::vector<Eigen::Vector3f>& points,
                                    const std::vector<MeasuredView>& views,
                                    bool zero_is_empty = false);

// One flag per point: 1 = made for a textureless surface. The point belongs
// to the view in which it lies nearest the ground-truth surface (relative
// depth difference at the pixel it projects to, among the views with ground
// truth there), and is textureless when that view's mask holds the pixel.
// Points that project onto no ground truth (the sky) and points of textured
// surfaces are 0: the part of a cloud whose accuracy says whether surfaces
// appear where the images give no evidence.
std::vector<uint8_t> OnTexturelessSurface(const std::vector<Eigen::Vector3f>& points,
                                          const std::vector<MeasuredView>& views);

}  // namespace eval
}  // namespace msp

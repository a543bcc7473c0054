// Textureless pixels of a real image, for the evaluator's textureless /
// textured split (a rendered scene knows its materials; a photograph does
// not). The rule: a pixel is textureless when the standard deviation of the
// grey image over the matching window around it (COLMAP's default
// window_radius 5: 11x11 pixels) is below kTexturelessStdDev grey levels,
// i.e. when a photo-consistency window there sees little but noise.
#pragma once

#include <opencv2/core.hpp>

namespace msp {
namespace rgbd {

constexpr int kTexturelessWindowRadius = 5;
// office-rgbd's white walls, grey doors and cabinet fronts sit at 1-3 levels
// over the window (sensor noise and shading), its wood, carpet and posters
// mostly above 5; 4 lies between. On the bundled scene (1 level of noise) it
// marks 80-83 % of the pixels its materials label textureless (the rest are
// within a window of a textured object) and none of the textured ones.
constexpr double kTexturelessStdDev = 4.0;

// CV_8UC1 at the image's size: 255 where textureless. `image` is 8-bit BGR
// (or grey).
cv::Mat TexturelessMask(const cv::Mat& image);

}  // namespace rgbd
}  // namespace msp

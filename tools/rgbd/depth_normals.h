// Ground-truth normals where only depth was measured: a sensor gives no
// normals, and the evaluator's normal errors need some. The rule: a pixel's
// normal is the normal of the least-squares plane through the back-projected
// pixels of its window (kNormalWindowRadius) that are measured and on its
// surface (depth within eval::kDepthEdgeJump of its own), when at least
// kMinNormalSupport of them are; otherwise it has none (0, 0, 0), which the
// evaluator leaves out. A window rather than the two neighbours because one
// pixel's depth step at 2-4 m is a few millimetres, the size of the sensor's
// noise and of a millimetre PNG's rounding.
#pragma once

#include "base/dense_map.h"
#include "tools/scene/camera_rig.h"

namespace msp {
namespace rgbd {

// 7x7 pixels: about 3-6 cm of a surface at 2-4 m with a 500 px focal length,
// flat on walls and furniture, wide enough to average the noise away.
constexpr int kNormalWindowRadius = 3;
// More than half the window's 49 pixels: the plane is the surface's own, not
// a corner's or a line of grid holes'.
constexpr int kMinNormalSupport = 25;

// Unit camera-frame normals facing the camera (COLMAP's convention), 3
// channels, (0, 0, 0) where the rule gives none. `view` back-projects the
// pixels (integer index = image point).
DenseMap NormalsFromDepth(const DenseMap& depth, const scene::PinholeView& view);

}  // namespace rgbd
}  // namespace msp

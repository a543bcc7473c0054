// The ground-truth surface sample of a sensor capture: the measured depth of
// every frame back-projected, one point per voxel, each with the number of
// frames that see it. A frame sees a sample when the sample projects inside
// its image, in front of it, onto a measured pixel (nearest) whose depth
// agrees with the sample's camera z within eval::kDepthEdgeJump: wider than
// the sensor's disagreement with itself across frames (about 1 %), narrower
// than a step to another surface.
#pragma once

#include <vector>

#include "base/dense_map.h"
#include "tools/scene/camera_rig.h"
#include "tools/scene/surface_sample.h"

namespace msp {
namespace rgbd {

// 5 mm: a quarter of the finest absolute threshold (2 cm), so the sample's
// gaps do not blur it, and about a pixel's footprint at 2.5 m with a 500 px
// focal length.
constexpr double kSensorSampleSpacing = 0.005;

// `normals` are the frames' camera-frame normal maps (NormalsFromDepth); a
// sample keeps the first back-projected pixel of its voxel (frame, row,
// column order) and that pixel's normal in world coordinates, (0, 0, 0) when
// it has none.
scene::SurfaceSample SampleMeasuredSurface(const std::vector<scene::PinholeView>& views,
                                           const std::vector<DenseMap>& depths,
                                           const std::vector<DenseMap>& normals,
                                           double spacing = kSensorSampleSpacing);

}  // namespace rgbd
}  // namespace msp

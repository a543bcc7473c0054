// Per-pixel features of the geometry label layers (docs/method.md section 4.1):
// the log depth in units of a relative depth jump and the unit normal in
// units of an angle, so that the Euclidean distance of two neighbours'
// features (the edge weight of the graph segmentation) grows with the
// relative depth jump between them, |ln d_p - ln d_q| ~ |d_p - d_q| / d, and
// with the angle between their normals, |n_p - n_q| = 2 sin(angle / 2).
// Host/device neutral.
#pragma once

#include <cmath>

#include "core/math/hd.h"

namespace msp {
namespace core {

constexpr int kNumGeometryFeatures = 4;  // ln d, n_x, n_y, n_z

struct GeometryFeatureUnits {
  float relative_depth;  // relative depth jump that weighs 1
  float normal_angle;    // angle between normals (radians) that weighs about 1
};

// A depth the geometry layers can use: positive and finite (0 = none).
MSP_HD bool HasGeometry(float depth) { return depth > 0.0f && depth < INFINITY; }

// The features of a pixel with depth `depth` > 0 and unit normal n.
MSP_HD void GeometryFeatures(float depth, float nx, float ny, float nz,
                             const GeometryFeatureUnits& units,
                             float features[kNumGeometryFeatures]) {
  features[0] = logf(depth) / units.relative_depth;
  features[1] = nx / units.normal_angle;
  features[2] = ny / units.normal_angle;
  features[3] = nz / units.normal_angle;
}

}  // namespace core
}  // namespace msp

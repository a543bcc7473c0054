// Sensor depth maps as RGB-D captures store them: single-channel 16-bit PNGs
// of depth along the camera's z axis in fixed units (1000 per metre =
// millimetres for most depth cameras and phone exports, 5000 per metre for
// TUM RGB-D), 0 = no measurement.
#pragma once

#include <string>

#include "base/dense_map.h"

namespace msp {
namespace rgbd {

// The depth in metres (0 stays 0 = no measurement). The PNG header's size is
// checked against width x height before the file is decoded. Throws
// InputError naming the file for a file that is not a PNG, of another size,
// not single-channel 16-bit, or undecodable.
DenseMap ReadDepthPng(const std::string& path, int width, int height, double units_per_metre);

}  // namespace rgbd
}  // namespace msp

// Reads the vertices of a PLY point cloud: COLMAP's fused.ply (binary little
// endian, x y z nx ny nz float, red green blue uchar) and the generator's
// ground_truth/surface.ply (x y z nx ny nz float, num_views uchar). ASCII
// files are accepted too. Only x, y, z and an optional num_views are kept.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace msp {
namespace eval {

struct PlyPoints {
  std::vector<Eigen::Vector3f> points;
  std::vector<uint8_t> num_views;  // empty unless the file has a num_views property
};

// Throws InputError naming the file on a missing file, an unsupported format
// or property type, or a truncated body.
PlyPoints ReadPlyPoints(const std::string& path);

}  // namespace eval
}  // namespace msp

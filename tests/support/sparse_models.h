// Builders of COLMAP sparse models (cameras, posed images, points and their
// tracks) for the workspace tests.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/sparse_model.h"

namespace msp {
namespace test {

inline SparseCamera MakeSparseCamera(uint32_t camera_id, int model_id, uint64_t width,
                                     uint64_t height, std::vector<double> params) {
  SparseCamera camera;
  camera.camera_id = camera_id;
  camera.model_id = model_id;
  camera.width = width;
  camera.height = height;
  camera.params = std::move(params);
  return camera;
}

// Image `image_id` of camera 1, named img<image_id>.png, looking along +z
// (identity rotation) from the centre (x, y, z): t = -R C = -C.
inline SparseImage ImageAt(uint32_t image_id, double x, double y, double z) {
  SparseImage image;
  image.image_id = image_id;
  image.camera_id = 1;
  image.name = "img" + std::to_string(image_id) + ".png";
  image.tvec[0] = -x;
  image.tvec[1] = -y;
  image.tvec[2] = -z;
  return image;
}

// Point (x, y, z) observed by the images `image_ids` (as their point2D 0).
inline SparsePoint3D PointAt(uint64_t point3D_id, double x, double y, double z,
                             const std::vector<uint32_t>& image_ids) {
  SparsePoint3D point;
  point.point3D_id = point3D_id;
  point.xyz[0] = x;
  point.xyz[1] = y;
  point.xyz[2] = z;
  for (const uint32_t id : image_ids) point.track.push_back({id, 0});
  return point;
}

}  // namespace test
}  // namespace msp

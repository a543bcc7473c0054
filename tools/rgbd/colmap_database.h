// The two things the importer needs from the database COLMAP's
// feature_extractor writes (SQLite, tables `images` and `cameras`): the ids
// it gave the images, which the known-pose model must reuse (point_triangulator
// matches the model's images to the database's by id and name), and the
// cameras' parameters, which are set to the known intrinsics so that
// matching's geometric verification uses them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace msp {
namespace rgbd {

struct DatabaseImage {
  uint32_t image_id = 0;
  uint32_t camera_id = 0;
  std::string name;
};

// The rows of `images`. Throws InputError naming the database when it cannot
// be opened or read.
std::vector<DatabaseImage> ReadDatabaseImages(const std::string& database_path);

// Makes camera `camera_id` a PINHOLE camera (COLMAP model id 1) of the given
// size and parameters (fx, fy, cx, cy), with prior_focal_length set: the
// intrinsics are known, not guessed. Throws InputError when no such camera
// exists or the update fails.
void SetPinholeCamera(const std::string& database_path, uint32_t camera_id, int width, int height,
                      const double params[4]);

}  // namespace rgbd
}  // namespace msp

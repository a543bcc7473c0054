// A posed RGB-D sequence as capture apps and datasets store it: a folder of
// colour images, a folder of 16-bit depth PNGs paired with them in sorted
// order, the pinhole intrinsics (one 3x3 K for every frame, or one per
// frame) and one camera-to-world pose per frame. Everything is checked
// before anything is written: counts that do not match, a K that is not a
// pinhole matrix and a pose that is not a rotation stop with one line naming
// the file and the value.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace msp {
namespace rgbd {

struct RgbdPaths {
  std::string images;      // colour images (.png, .jpg, .jpeg), sorted by file name
  std::string depth;       // depth PNGs (.png), paired with the images in sorted order
  std::string intrinsics;  // K.txt: 9 numbers (row-major 3x3, all frames) or 9 per frame
  std::string poses;       // poses.txt: a row-major 4x4 camera-to-world matrix per line
};

struct RgbdFrame {
  std::string name;  // the colour image's file name, the model's image name
  std::string image_path;
  std::string depth_path;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;           // as K.txt gives them
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // camera -> world, orthonormalised
  Eigen::Vector3d center = Eigen::Vector3d::Zero();        // camera centre in the world
};

// How far R^T R may be from the identity (largest entry) for a pose to count
// as a rotation: poses printed with 5-6 significant digits are off by ~1e-5
// (office-rgbd's by 8e-6), a scaled, sheared or transposed matrix by far
// more. The accepted matrix is replaced by its nearest rotation.
constexpr double kRotationTolerance = 1e-4;

// The frames in sorted image order. Throws InputError naming the file and the
// value for a missing folder, mismatched counts, a malformed or non-pinhole
// K (skew, a non-positive focal length, a last row other than 0 0 1), or a
// pose whose last row is not 0 0 0 1 or whose 3x3 part is not a rotation
// (kRotationTolerance, determinant +1).
std::vector<RgbdFrame> ReadRgbdSequence(const RgbdPaths& paths);

// The nearest rotation to `m` (SVD), or false when `m` is not within
// kRotationTolerance of one or is a reflection; `why` then says which.
bool NearestRotation(const Eigen::Matrix3d& m, Eigen::Matrix3d* rotation, std::string* why);

}  // namespace rgbd
}  // namespace msp

// A sparse camera and image as the core's camera (MakeCoreCamera): which
// sparse cameras dense stereo can use, and rescaling a camera to the working
// resolution.
#pragma once

#include <string>

#include "core/math/camera.h"
#include "io/sparse_model.h"

namespace msp {

// Converts a sparse camera + image pose to the core camera; throws InputError
// for a distorted camera ("run colmap image_undistorter").
core::Camera MakeCoreCamera(const SparseCamera& camera, const SparseImage& image);

// Scale factor and size of COLMAP's Downsize for a maximum side (<= 0: none).
void DownsizedSize(int width, int height, int max_image_size, int* new_width, int* new_height);

struct PinholeIntrinsics {
  double fx, fy, cx, cy;
};

struct PinholeCheck {
  bool ok;
  std::string message;  // why not, naming the camera and image, when !ok
};

// Accepts SIMPLE_PINHOLE, PINHOLE and any COLMAP 3.8 model whose distortion
// parameters are all zero, with a positive focal length and a sane size.
PinholeCheck CheckPinholeCamera(const SparseCamera& camera, const SparseImage& image,
                                PinholeIntrinsics* intrinsics);

// The pose of `image` (R, t, center) with zero size and intrinsics: used for
// views that no problem reads, whose camera may not be usable.
core::Camera MakePoseOnlyCamera(const SparseImage& image);

// Scales fx, cx by new_width / width and fy, cy by new_height / height, then
// sets the new size.
void ResizeCamera(int new_width, int new_height, core::Camera* cam);

}  // namespace msp

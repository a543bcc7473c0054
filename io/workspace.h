// A COLMAP dense workspace (the output of `colmap image_undistorter`) read into
// the plain structs of src/base/mvs_input.h, and the paths of the maps written back.
#pragma once

#include <string>
#include <vector>

#include "base/mvs_input.h"
#include "io/sparse_model.h"
#include "options/stereo_options.h"

namespace msp {

struct Workspace {
  std::string path;
  // Cameras and image poses; the points and 2D observations are dropped
  // once the problems and depth ranges are made (they grow with the images).
  SparseModel model;
  // One view per model image, in model order (= COLMAP's mvs::Model index).
  // Images (gray/color) are loaded only for views used by some problem.
  std::vector<View> views;
  std::vector<Problem> problems;
};

// Reads <workspace_path>/sparse, the problems of stereo/patch-match.cfg (or
// options.config_path), the images used by them from images/<name>, downsized
// to --PatchMatchStereo.max_image_size with the intrinsics scaled as COLMAP's
// mvs::Image::Downsize does. Cameras must be SIMPLE_PINHOLE, PINHOLE or a
// model whose distortion parameters are all zero. With the segmentation prior
// (and deformable patches) on, the reference views' mask layers are read from
// --MspStereo.mask_path (default <workspace>/masks) and the source of each is
// logged. Throws InputError with a specific message on every bad input.
Workspace LoadWorkspace(const StereoCommandOptions& options);

// <ws>/stereo/{depth,normal}_maps/<name>.<type>.bin, type "photometric" or "geometric".
std::string DepthMapPath(const std::string& workspace_path, const std::string& image_name,
                         const std::string& type);
std::string NormalMapPath(const std::string& workspace_path, const std::string& image_name,
                          const std::string& type);

// Writes stereo/fusion.cfg (one image name per line, problem order) unless it exists.
void WriteFusionConfigIfMissing(const Workspace& workspace);

}  // namespace msp

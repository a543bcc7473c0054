// msp_import_rgbd's job: a posed RGB-D sequence (rgbd_sequence.h) in, a
// COLMAP dense workspace with sensor ground truth out. The selected frames'
// images and depth are checked first; then COLMAP triangulates SIFT tracks
// with the poses held fixed and undistorts into the workspace
// (colmap_steps.h), and ground_truth/ is written (sensor_ground_truth.h).
// Everything is made in a temporary folder next to the output and renamed
// at the end, so a failure leaves nothing behind.
#pragma once

#include <string>
#include <vector>

#include "tools/rgbd/frame_selection.h"
#include "tools/rgbd/rgbd_sequence.h"

namespace msp {
namespace rgbd {

struct ImportOptions {
  // A folder with images/, depth/, K.txt and poses.txt; each of `paths` that
  // is empty defaults to the matching one inside it.
  std::string input;
  RgbdPaths paths;
  std::string output;  // the workspace to write; must not exist
  // Depth PNG units per metre: 1000 for millimetres, 5000 for TUM RGB-D.
  // Required (0 = not given): a wrong scale would silently scale the truth.
  double depth_units_per_metre = 0.0;
  // What K's principal point needs added to be in COLMAP's convention, where
  // the centre of pixel (0, 0) is the point (0.5, 0.5): 0.5 when K puts
  // pixel centres at integer coordinates (OpenCV, most RGB-D datasets and
  // phone exports), 0 when K already uses COLMAP's convention.
  double pixel_centre_offset = 0.5;
  FrameSelection selection;
  std::string colmap = "colmap";
  int num_threads = -1;
};

// |pixel_centre_offset| beyond a pixel is a different principal point, not
// a convention.
constexpr double kMaxPixelCentreOffset = 1.0;

struct ImportSummary {
  std::vector<int> frames;  // selected indices in sorted image order
  int num_points3D = 0;
  double mean_track_length = 0.0;
  double mean_reprojection_error = 0.0;
  int num_surface_samples = 0;
  double extent = 0.0;
  double measured_fraction = 0.0;  // of the selected frames' pixels
};

// Throws InputError (one line naming the file or option) on bad input or a
// failed COLMAP step; the output then does not exist.
ImportSummary ImportRgbd(const ImportOptions& options);

// The PINHOLE parameters (fx, fy, cx, cy) of `frame` in COLMAP's convention.
void ColmapIntrinsics(const RgbdFrame& frame, double pixel_centre_offset, double params[4]);

}  // namespace rgbd
}  // namespace msp

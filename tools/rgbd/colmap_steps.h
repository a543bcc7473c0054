// The sparse and dense preparation of a posed capture with the real COLMAP,
// as its FAQ describes for known poses: SIFT features, exhaustive matching,
// point_triangulator on a model whose cameras and poses are given (COLMAP
// keeps them fixed), then image_undistorter into a dense workspace. SIFT
// runs on the CPU (Debian's COLMAP without a display cannot make the OpenGL
// context SiftGPU needs).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/sparse_model.h"

namespace msp {
namespace rgbd {

// One image of the known-pose model.
struct KnownView {
  std::string name;  // file name in image_dir
  int width = 0;
  int height = 0;
  double params[4] = {0, 0, 0, 0};                  // PINHOLE fx, fy, cx, cy in COLMAP's convention
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // world -> camera
  Eigen::Vector3d t = Eigen::Vector3d::Zero();      // X_cam = R X_world + t
};

struct ColmapStepsOptions {
  std::string colmap = "colmap";  // the real COLMAP binary (or our dispatcher)
  std::string image_dir;          // where the views' images are
  std::string project_dir;        // database, models and logs (created)
  std::string workspace_dir;      // image_undistorter's output
  int num_threads = -1;           // SIFT extraction and matching; -1 = all cores
  bool shared_camera = true;      // one camera for every view (one K)
};

struct ColmapStepsSummary {
  int num_points3D = 0;
  double mean_track_length = 0.0;
  double mean_reprojection_error = 0.0;  // pixels, COLMAP's per-point errors
};

// Runs the four steps, logging each to <project_dir>/<step>.log. Checks that
// COLMAP kept every camera and pose (InputError otherwise) and that tracks
// were triangulated. Throws InputError naming the failed step and its log.
ColmapStepsSummary RunColmapSteps(const ColmapStepsOptions& options,
                                  const std::vector<KnownView>& views);

// The known-pose model: `views` with the image and camera ids that
// feature_extractor gave them (read from its database), no points.
SparseModel KnownPoseModel(const std::vector<KnownView>& views, const std::string& database_path);

// Throws InputError when `model` does not hold `views` with the same
// intrinsics, size and pose (within round-off: kPoseTolerance).
void CheckKeptPoses(const SparseModel& model, const std::vector<KnownView>& views,
                    const std::string& what);

// COLMAP stores the poses and intrinsics as doubles and keeps them fixed,
// but they pass through a quaternion and back: allow a few ulps of a
// quaternion's round trip.
constexpr double kPoseTolerance = 1e-9;

}  // namespace rgbd
}  // namespace msp

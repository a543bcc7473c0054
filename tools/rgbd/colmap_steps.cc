#include "tools/rgbd/colmap_steps.h"

#include <Eigen/Geometry>
#include <cmath>

#include "io/errors.h"
#include "io/file_util.h"
#include "tools/rgbd/colmap_database.h"
#include "tools/rgbd/run_command.h"
#include "tools/scene/camera_rig.h"

namespace msp {
namespace rgbd {
namespace {

std::string Flag(bool value) { return value ? "1" : "0"; }

void ExtractFeatures(const ColmapStepsOptions& o, const std::string& database,
                     const std::vector<KnownView>& views) {
  const std::string list = JoinPaths(o.project_dir, "image_list.txt");
  std::string names;
  for (const KnownView& view : views) names += view.name + "\n";
  WriteFileAtomic(list, names);
  RunCommandOrThrow(
      {o.colmap, "feature_extractor", "--database_path", database, "--image_path", o.image_dir,
       "--image_list_path", list, "--ImageReader.camera_model", "PINHOLE",
       "--ImageReader.single_camera", Flag(o.shared_camera),
       "--ImageReader.single_camera_per_image", Flag(!o.shared_camera), "--SiftExtraction.use_gpu",
       "0", "--SiftExtraction.num_threads", std::to_string(o.num_threads)},
      JoinPaths(o.project_dir, "feature_extractor.log"));
}

// The database's cameras get the known intrinsics, so that matching's
// geometric verification uses them.
void SetDatabaseCameras(const std::string& database, const SparseModel& model) {
  for (const SparseCamera& camera : model.cameras) {
    SetPinholeCamera(database, camera.camera_id, static_cast<int>(camera.width),
                     static_cast<int>(camera.height), camera.params.data());
  }
}

double MaxDifference(const double* a, const double* b, int n) {
  double worst = 0.0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

}  // namespace

SparseModel KnownPoseModel(const std::vector<KnownView>& views, const std::string& database_path) {
  const std::vector<DatabaseImage> db_images = ReadDatabaseImages(database_path);
  SparseModel model;
  for (const KnownView& view : views) {
    const DatabaseImage* found = nullptr;
    for (const DatabaseImage& image : db_images) {
      if (image.name == view.name) found = &image;
    }
    if (found == nullptr) {
      throw InputError("COLMAP's feature_extractor did not add " + view.name + " to " +
                       database_path + " (unreadable image?)");
    }
    if (model.FindCamera(found->camera_id) < 0) {
      SparseCamera camera;
      camera.camera_id = found->camera_id;
      camera.model_id = kPinhole;
      camera.width = static_cast<uint64_t>(view.width);
      camera.height = static_cast<uint64_t>(view.height);
      camera.params.assign(view.params, view.params + 4);
      model.cameras.push_back(camera);
    }
    SparseImage image;
    image.image_id = found->image_id;
    image.camera_id = found->camera_id;
    image.name = view.name;
    scene::RotationToQuaternion(view.R, image.qvec);
    for (int k = 0; k < 3; ++k) image.tvec[k] = view.t[k];
    model.images.push_back(image);
  }
  return model;
}

void CheckKeptPoses(const SparseModel& model, const std::vector<KnownView>& views,
                    const std::string& what) {
  for (const KnownView& view : views) {
    const int i = model.FindImageByName(view.name);
    if (i < 0) throw InputError(what + ": image " + view.name + " is missing");
    const SparseImage& image = model.images[i];
    const int c = model.FindCamera(image.camera_id);
    if (c < 0) throw InputError(what + ": the camera of " + view.name + " is missing");
    const SparseCamera& camera = model.cameras[c];
    const Eigen::Matrix3d R =
        Eigen::Quaterniond(image.qvec[0], image.qvec[1], image.qvec[2], image.qvec[3])
            .toRotationMatrix();
    const bool same_camera = camera.model_id == kPinhole && camera.params.size() == 4 &&
                             camera.width == static_cast<uint64_t>(view.width) &&
                             camera.height == static_cast<uint64_t>(view.height) &&
                             MaxDifference(camera.params.data(), view.params, 4) <= kPoseTolerance;
    const bool same_pose = MaxDifference(R.data(), view.R.data(), 9) <= kPoseTolerance &&
                           MaxDifference(image.tvec, view.t.data(), 3) <= kPoseTolerance;
    if (!same_camera || !same_pose) {
      throw InputError(what + ": COLMAP changed the " + (same_camera ? "pose" : "camera") + " of " +
                       view.name + ", which must stay as given");
    }
  }
}

ColmapStepsSummary RunColmapSteps(const ColmapStepsOptions& o,
                                  const std::vector<KnownView>& views) {
  CreateDirectories(o.project_dir);
  const std::string database = JoinPaths(o.project_dir, "database.db");
  ExtractFeatures(o, database, views);
  const SparseModel known = KnownPoseModel(views, database);
  SetDatabaseCameras(database, known);
  const std::string known_dir = JoinPaths(o.project_dir, "known_poses");
  WriteSparseModelText(known, known_dir);
  RunCommandOrThrow(
      {o.colmap, "exhaustive_matcher", "--database_path", database, "--SiftMatching.use_gpu", "0",
       "--SiftMatching.num_threads", std::to_string(o.num_threads)},
      JoinPaths(o.project_dir, "exhaustive_matcher.log"));
  const std::string triangulated_dir = JoinPaths(o.project_dir, "triangulated");
  CreateDirectories(triangulated_dir);
  RunCommandOrThrow({o.colmap, "point_triangulator", "--database_path", database, "--image_path",
                     o.image_dir, "--input_path", known_dir, "--output_path", triangulated_dir},
                    JoinPaths(o.project_dir, "point_triangulator.log"));
  const SparseModel triangulated = ReadSparseModel(triangulated_dir);
  CheckKeptPoses(triangulated, views, triangulated_dir);
  if (triangulated.points3D.empty()) {
    throw InputError("COLMAP triangulated no point (" + triangulated_dir +
                     "): do the selected frames overlap? (--frames, --step, --min_baseline)");
  }
  RunCommandOrThrow({o.colmap, "image_undistorter", "--image_path", o.image_dir, "--input_path",
                     triangulated_dir, "--output_path", o.workspace_dir, "--output_type", "COLMAP"},
                    JoinPaths(o.project_dir, "image_undistorter.log"));
  CheckKeptPoses(ReadSparseModel(JoinPaths(o.workspace_dir, "sparse")), views,
                 JoinPaths(o.workspace_dir, "sparse"));
  ColmapStepsSummary summary;
  summary.num_points3D = static_cast<int>(triangulated.points3D.size());
  size_t observations = 0;
  double error = 0.0;
  for (const SparsePoint3D& p : triangulated.points3D) {
    observations += p.track.size();
    error += p.error;
  }
  summary.mean_track_length = static_cast<double>(observations) / summary.num_points3D;
  summary.mean_reprojection_error = error / summary.num_points3D;
  return summary;
}

}  // namespace rgbd
}  // namespace msp

#include "tools/rgbd/import_rgbd.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "io/errors.h"
#include "io/file_util.h"
#include "tools/rgbd/colmap_steps.h"
#include "tools/rgbd/depth_png.h"
#include "tools/rgbd/sensor_ground_truth.h"

namespace msp {
namespace rgbd {
namespace {

namespace fs = std::filesystem;

// COLMAP's convention puts the centre of pixel (0, 0) at (0.5, 0.5); the
// true ray of pixel index i therefore passes through cx_colmap - 0.5.
constexpr double kColmapPixelCentre = 0.5;

// The folder that becomes the output, removed unless committed.
class StagingDir {
 public:
  explicit StagingDir(const std::string& output)
      : output_(output), path_(TemporaryPath(output, static_cast<long>(::getpid()))) {
    std::error_code ignored;
    fs::remove_all(path_, ignored);  // a leftover of a killed run with our pid
    CreateDirectories(path_);
  }
  ~StagingDir() {
    if (committed_) return;
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  StagingDir(const StagingDir&) = delete;
  StagingDir& operator=(const StagingDir&) = delete;

  const std::string& path() const { return path_; }
  void Commit() {
    std::error_code ec;
    fs::rename(path_, output_, ec);
    if (ec) throw InputError("cannot rename " + path_ + " to " + output_ + ": " + ec.message());
    committed_ = true;
  }

 private:
  std::string output_;
  std::string path_;
  bool committed_ = false;
};

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

RgbdPaths ResolvePaths(const ImportOptions& o) {
  RgbdPaths p = o.paths;
  const bool complete =
      !p.images.empty() && !p.depth.empty() && !p.intrinsics.empty() && !p.poses.empty();
  if (o.input.empty() && !complete) {
    throw InputError("give --input, or all of --images, --depth, --intrinsics and --poses");
  }
  if (p.images.empty()) p.images = JoinPaths(o.input, "images");
  if (p.depth.empty()) p.depth = JoinPaths(o.input, "depth");
  if (p.intrinsics.empty()) p.intrinsics = JoinPaths(o.input, "K.txt");
  if (p.poses.empty()) p.poses = JoinPaths(o.input, "poses.txt");
  return p;
}

void CheckOptions(const ImportOptions& o) {
  if (o.output.empty()) throw InputError("--output is required");
  if (fs::exists(o.output)) {
    throw InputError("--output " + o.output + " exists; remove it or choose another folder");
  }
  if (!(o.depth_units_per_metre > 0.0) || !std::isfinite(o.depth_units_per_metre)) {
    throw InputError(
        "--depth_units_per_metre is required and positive: the depth PNGs' units per metre "
        "(1000 for millimetres, 5000 for TUM RGB-D)");
  }
  if (!(std::abs(o.pixel_centre_offset) <= kMaxPixelCentreOffset)) {
    throw InputError("--pixel_centre_offset must be within [-1, 1] (0.5 or 0 in practice)");
  }
}

// The selected frames' images and depth, read and checked before COLMAP runs.
struct LoadedFrame {
  const RgbdFrame* frame = nullptr;
  int width = 0;
  int height = 0;
  DenseMap depth;
};

LoadedFrame LoadFrame(const RgbdFrame& frame, double units_per_metre) {
  const cv::Mat image = cv::imread(frame.image_path, cv::IMREAD_COLOR);
  if (image.empty()) throw InputError("cannot read image " + frame.image_path);
  LoadedFrame loaded;
  loaded.frame = &frame;
  loaded.width = image.cols;
  loaded.height = image.rows;
  loaded.depth = ReadDepthPng(frame.depth_path, image.cols, image.rows, units_per_metre);
  return loaded;
}

KnownView MakeKnownView(const LoadedFrame& loaded, double offset) {
  KnownView view;
  view.name = loaded.frame->name;
  view.width = loaded.width;
  view.height = loaded.height;
  ColmapIntrinsics(*loaded.frame, offset, view.params);
  view.R = loaded.frame->rotation.transpose();
  view.t = -view.R * loaded.frame->center;
  return view;
}

// The view of the true rays: pixel index i at cx_colmap - 0.5.
scene::PinholeView TrueView(const KnownView& known) {
  scene::PinholeView view;
  view.name = known.name;
  view.width = known.width;
  view.height = known.height;
  view.fx = known.params[0];
  view.fy = known.params[1];
  view.cx = known.params[2] - kColmapPixelCentre;
  view.cy = known.params[3] - kColmapPixelCentre;
  view.R = known.R;
  view.t = known.t;
  return view;
}

bool SameCamera(const KnownView& a, const KnownView& b) {
  return a.width == b.width && a.height == b.height && a.params[0] == b.params[0] &&
         a.params[1] == b.params[1] && a.params[2] == b.params[2] && a.params[3] == b.params[3];
}

std::vector<std::pair<std::string, std::string>> Header(const ImportOptions& o,
                                                        const RgbdPaths& paths,
                                                        const std::vector<int>& frames) {
  std::ostringstream source, list;
  source << "sensor depth PNGs, " << o.depth_units_per_metre << " units per metre";
  list << "[";
  for (size_t i = 0; i < frames.size(); ++i) list << (i ? ", " : "") << frames[i];
  list << "]";
  std::ostringstream offset;
  offset << o.pixel_centre_offset;
  return {{"depth_source", JsonString(source.str())}, {"images", JsonString(paths.images)},
          {"depth", JsonString(paths.depth)},         {"intrinsics", JsonString(paths.intrinsics)},
          {"poses", JsonString(paths.poses)},         {"frames", list.str()},
          {"pixel_centre_offset", offset.str()}};
}

}  // namespace

void ColmapIntrinsics(const RgbdFrame& frame, double pixel_centre_offset, double params[4]) {
  params[0] = frame.fx;
  params[1] = frame.fy;
  params[2] = frame.cx + pixel_centre_offset;
  params[3] = frame.cy + pixel_centre_offset;
}

ImportSummary ImportRgbd(const ImportOptions& options) {
  ImportOptions o = options;
  // "ws/" must stage at "ws.tmp-<pid>", beside the output, not inside it.
  while (o.output.size() > 1 && o.output.back() == '/') o.output.pop_back();
  CheckOptions(o);
  const RgbdPaths paths = ResolvePaths(o);
  const std::vector<RgbdFrame> frames = ReadRgbdSequence(paths);
  std::vector<Eigen::Vector3d> centers;
  for (const RgbdFrame& frame : frames) centers.push_back(frame.center);
  ImportSummary summary;
  summary.frames = SelectFrames(centers, o.selection);
  std::vector<LoadedFrame> loaded;
  std::vector<KnownView> known;
  for (const int i : summary.frames) {
    loaded.push_back(LoadFrame(frames[i], o.depth_units_per_metre));
    known.push_back(MakeKnownView(loaded.back(), o.pixel_centre_offset));
  }
  StagingDir staging(o.output);
  ColmapStepsOptions steps;
  steps.colmap = o.colmap;
  steps.image_dir = paths.images;
  steps.project_dir = JoinPaths(staging.path(), "rgbd_import");
  steps.workspace_dir = staging.path();
  steps.num_threads = o.num_threads;
  for (const KnownView& view : known) steps.shared_camera &= SameCamera(view, known.front());
  const ColmapStepsSummary sparse = RunColmapSteps(steps, known);

  std::vector<SensorFrame> sensor(loaded.size());
  for (size_t i = 0; i < loaded.size(); ++i) {
    sensor[i].view = TrueView(known[i]);
    // The image the stereo method will see: the workspace's copy.
    const std::string path = JoinPaths(staging.path(), "images/" + known[i].name);
    sensor[i].image = cv::imread(path, cv::IMREAD_COLOR);
    if (sensor[i].image.cols != known[i].width || sensor[i].image.rows != known[i].height) {
      throw InputError(path + ": image_undistorter did not copy the image at its size");
    }
    sensor[i].depth = std::move(loaded[i].depth);
  }
  const SensorGroundTruthSummary gt =
      WriteSensorGroundTruth(staging.path(), sensor, Header(o, paths, summary.frames));
  staging.Commit();

  summary.num_points3D = sparse.num_points3D;
  summary.mean_track_length = sparse.mean_track_length;
  summary.mean_reprojection_error = sparse.mean_reprojection_error;
  summary.num_surface_samples = gt.num_surface_samples;
  summary.extent = gt.extent;
  summary.measured_fraction = gt.measured_fraction;
  return summary;
}

}  // namespace rgbd
}  // namespace msp

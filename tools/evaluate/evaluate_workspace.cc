#include "tools/evaluate/evaluate_workspace.h"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "io/camera_conversion.h"
#include "io/dense_map_io.h"
#include "io/errors.h"
#include "io/map_previews.h"
#include "io/sparse_model.h"
#include "io/workspace.h"
#include "tools/evaluate/edge_regions.h"
#include "tools/evaluate/measured_points.h"
#include "tools/evaluate/ply_points.h"

namespace msp {
namespace eval {
namespace {

std::string MapPath(const std::string& workspace, const char* folder, const std::string& name,
                    const std::string& type) {
  return workspace + "/stereo/" + folder + "/" + name + "." + type + ".bin";
}

DepthThresholds Thresholds(const GroundTruthInfo& info) {
  DepthThresholds t;
  for (int k = 0; k < 2; ++k) {
    t.relative[k] = info.depth_relative_thresholds[k];
    t.absolute[k] = info.absolute_thresholds_m[k];
  }
  return t;
}

// The ground-truth views with the workspace's cameras, for MeasuredPoints.
std::vector<MeasuredView> MeasuredViews(const std::string& workspace, const GroundTruthInfo& info) {
  const SparseModel model = ReadSparseModel(workspace + "/sparse");
  std::vector<MeasuredView> views;
  for (const std::string& name : info.image_names) {
    const int image = model.FindImageByName(name);
    const int camera = image < 0 ? -1 : model.FindCamera(model.images[image].camera_id);
    if (camera < 0) {
      throw InputError(workspace + "/sparse: no image `" + name + "` of the ground truth");
    }
    MeasuredView view;
    view.depth = ReadDenseMap(info.DepthMapPath(name));
    if (info.has_textureless) {
      view.textureless = cv::imread(info.TexturelessPath(name), cv::IMREAD_GRAYSCALE);
      if (view.textureless.empty()) throw InputError("cannot read " + info.TexturelessPath(name));
    }
    view.camera = MakeCoreCamera(model.cameras[camera], model.images[image]);
    ResizeCamera(view.depth.width, view.depth.height, &view.camera);
    views.push_back(std::move(view));
  }
  return views;
}

DepthMapMetrics EvaluateOne(const EvaluationOptions& options, const GroundTruthInfo& info,
                            const std::string& name) {
  DepthMapMetrics m;
  m.name = name;
  const std::string depth_path = MapPath(options.workspace, "depth_maps", name, options.input_type);
  if (!std::filesystem::exists(depth_path)) {
    m.missing = true;
    return m;
  }
  const DenseMap depth = ReadDenseMap(depth_path);
  if (depth.channels != 1) throw InputError(depth_path + ": a depth map has 1 channel");
  const std::string normal_path =
      MapPath(options.workspace, "normal_maps", name, options.input_type);
  DenseMap normal;
  if (std::filesystem::exists(normal_path)) normal = ReadDenseMap(normal_path);
  const DenseMap gt_depth = ReadDenseMap(info.DepthMapPath(name));
  const DenseMap gt_normal = info.has_normals ? ReadDenseMap(info.NormalMapPath(name)) : DenseMap();
  RegionMasks masks;
  if (info.has_textureless) {
    masks.textureless = cv::imread(info.TexturelessPath(name), cv::IMREAD_GRAYSCALE);
    if (masks.textureless.empty()) throw InputError("cannot read " + info.TexturelessPath(name));
  }
  // The edges' colours are those the method saw: the workspace's own image.
  const std::string image_path = options.workspace + "/images/" + name;
  const cv::Mat image = cv::imread(image_path, cv::IMREAD_COLOR);
  if (image.empty()) throw InputError("cannot read " + image_path);
  if (image.cols != gt_depth.width || image.rows != gt_depth.height) {
    throw InputError(image_path + " is not the size of its ground truth");
  }
  const int band = EdgeBandRadius(gt_depth.width, gt_depth.height, depth.width, depth.height);
  const EdgeRegions edges = FindEdgeRegions(gt_depth, image, band);
  masks.near_edge = edges.near_edge;
  masks.alike_edge = edges.alike_edge;
  m = EvaluateDepthMap(depth, normal, gt_depth, gt_normal, masks, Thresholds(info),
                       info.ZeroDepthIsEmpty());
  m.name = name;
  m.edge_band_radius = band;
  return m;
}

}  // namespace

EvaluationResult EvaluateWorkspace(const EvaluationOptions& options) {
  EvaluationResult result;
  result.info = ReadGroundTruthInfo(GroundTruthDir(options.workspace, options.ground_truth));
  result.input_type = options.input_type;
  if (options.evaluate_maps) {
    for (const std::string& name : result.info.image_names) {
      result.maps.push_back(EvaluateOne(options, result.info, name));
      result.maps.back().previews = ExistingPreviews(options.workspace, name);
      result.num_missing_maps += result.maps.back().missing ? 1 : 0;
    }
    result.average = AverageMetrics(result.maps);
  }
  if (!options.fused.empty()) {
    const GroundTruthInfo& info = result.info;
    const PlyPoints fused = ReadPlyPoints(options.fused);
    const PlyPoints gt = ReadPlyPoints(info.SurfacePath());
    const std::vector<CloudThreshold> thresholds = CloudThresholds(
        info.extent,
        {std::begin(info.cloud_threshold_fractions), std::end(info.cloud_threshold_fractions)},
        {std::begin(info.absolute_thresholds_m), std::end(info.absolute_thresholds_m)});
    const std::vector<MeasuredView> views = MeasuredViews(options.workspace, info);
    const std::vector<uint8_t> judged =
        MeasuredPoints(fused.points, views, info.ZeroDepthIsEmpty());
    result.has_cloud = true;
    result.fused = options.fused;
    result.cloud = EvaluateCloud(fused.points, judged, gt.points, gt.num_views,
                                 info.min_views_for_completeness, info.extent, thresholds);
    if (info.has_textureless) {
      // The same cloud judged on the points off textureless surfaces only.
      std::vector<uint8_t> off = OnTexturelessSurface(fused.points, views);
      for (size_t i = 0; i < off.size(); ++i) off[i] = judged[i] && !off[i];
      result.has_cloud_off_textureless = true;
      result.cloud_off_textureless =
          EvaluateCloud(fused.points, off, gt.points, gt.num_views, info.min_views_for_completeness,
                        info.extent, thresholds);
    }
  }
  return result;
}

}  // namespace eval
}  // namespace msp

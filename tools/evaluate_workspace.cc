#include "tools/evaluate_workspace.h"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "colmap_ext/dense_map_io.h"
#include "colmap_ext/errors.h"
#include "colmap_ext/map_previews.h"
#include "tools/edge_regions.h"
#include "tools/ply_points.h"

namespace msp {
namespace eval {
namespace {

std::string MapPath(const std::string& workspace, const char* folder, const std::string& name,
                    const std::string& type) {
  return workspace + "/stereo/" + folder + "/" + name + "." + type + ".bin";
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
  const DenseMap gt_normal = ReadDenseMap(info.NormalMapPath(name));
  RegionMasks masks;
  masks.textureless = cv::imread(info.TexturelessPath(name), cv::IMREAD_GRAYSCALE);
  if (masks.textureless.empty()) throw InputError("cannot read " + info.TexturelessPath(name));
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
  m = EvaluateDepthMap(depth, normal, gt_depth, gt_normal, masks, info.depth_relative_thresholds);
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
    const PlyPoints fused = ReadPlyPoints(options.fused);
    const PlyPoints gt = ReadPlyPoints(result.info.SurfacePath());
    const std::vector<double> fractions(std::begin(result.info.cloud_threshold_fractions),
                                        std::end(result.info.cloud_threshold_fractions));
    result.has_cloud = true;
    result.fused = options.fused;
    result.cloud =
        EvaluateCloud(fused.points, gt.points, gt.num_views, result.info.min_views_for_completeness,
                      result.info.extent, fractions);
  }
  return result;
}

}  // namespace eval
}  // namespace msp

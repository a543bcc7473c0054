#include "tools/rgbd/sensor_ground_truth.h"

#include <sstream>

#include "tools/evaluate/edge_regions.h"
#include "tools/rgbd/depth_normals.h"
#include "tools/rgbd/measured_surface.h"
#include "tools/rgbd/textureless_mask.h"
#include "tools/scene/renderer.h"
#include "tools/scene/scene_writer.h"

namespace msp {
namespace rgbd {
namespace {

std::string Quoted(const std::string& text) { return "\"" + text + "\""; }

}  // namespace

std::string NormalsRule() {
  const int side = 2 * kNormalWindowRadius + 1;
  std::ostringstream s;
  s << "least-squares plane of the measured pixels of the " << side << "x" << side
    << " window whose depth is within " << 100.0 * eval::kDepthEdgeJump
    << " % of the pixel's, when at least " << kMinNormalSupport << " of the " << side * side
    << " qualify; none otherwise";
  return s.str();
}

std::string TexturelessRule() {
  const int side = 2 * kTexturelessWindowRadius + 1;
  std::ostringstream s;
  s << "grey-level standard deviation over the " << side << "x" << side << " matching window below "
    << kTexturelessStdDev << " levels";
  return s.str();
}

SensorGroundTruthSummary WriteSensorGroundTruth(
    const std::string& workspace, const std::vector<SensorFrame>& frames,
    const std::vector<std::pair<std::string, std::string>>& header) {
  std::vector<scene::PinholeView> views;
  std::vector<scene::RenderedView> maps(frames.size());
  std::vector<DenseMap> depths, normals;
  size_t measured = 0, pixels = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const SensorFrame& frame = frames[i];
    views.push_back(frame.view);
    maps[i].depth = frame.depth;
    maps[i].normal = NormalsFromDepth(frame.depth, frame.view);
    maps[i].textureless = TexturelessMask(frame.image);
    depths.push_back(maps[i].depth);
    normals.push_back(maps[i].normal);
    for (const float d : frame.depth.data) measured += d > 0.0f ? 1 : 0;
    pixels += frame.depth.data.size();
  }
  const scene::SurfaceSample sample = SampleMeasuredSurface(views, depths, normals);
  std::vector<std::pair<std::string, std::string>> entries = header;
  entries.emplace_back("normals_rule", Quoted(NormalsRule()));
  entries.emplace_back("textureless_rule", Quoted(TexturelessRule()));
  entries.emplace_back("surface_sample_rule",
                       Quoted("measured depth back-projected, one point per voxel; a frame sees a "
                              "point on a measured pixel within the depth-edge jump"));
  scene::WriteGroundTruth(workspace, views, maps, sample,
                          scene::GroundTruthJson(views, sample, entries));
  SensorGroundTruthSummary summary;
  summary.num_surface_samples = static_cast<int>(sample.points.size());
  summary.extent = sample.Extent();
  summary.measured_fraction = pixels > 0 ? static_cast<double>(measured) / pixels : 0.0;
  return summary;
}

}  // namespace rgbd
}  // namespace msp

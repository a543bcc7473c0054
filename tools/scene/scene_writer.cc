#include "tools/scene/scene_writer.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

#include "io/dense_map_io.h"
#include "io/mask_layers.h"

namespace msp {
namespace scene {
namespace {

namespace fs = std::filesystem;

// Creates the parent folder of a file: image names may contain folders.
void MakeParent(const fs::path& path) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
}

void WriteText(const fs::path& path, const std::string& text) {
  MakeParent(path);
  std::ofstream file(path, std::ios::binary);
  file << text;
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

void WritePng(const fs::path& path, const cv::Mat& image) {
  MakeParent(path);
  if (!cv::imwrite(path.string(), image)) throw std::runtime_error("cannot write " + path.string());
}

// The scripts exactly as COLMAP's WriteCOLMAPCommands generates them.
std::string RunScript(bool geometric) {
  const char* type = geometric ? "geometric" : "photometric";
  std::ostringstream s;
  s << "# You must set $COLMAP_EXE_PATH to \n"
    << "# the directory containing the COLMAP executables.\n"
    << "$COLMAP_EXE_PATH/colmap patch_match_stereo \\\n"
    << "  --workspace_path . \\\n"
    << "  --workspace_format COLMAP \\\n"
    << "  --PatchMatchStereo.max_image_size 2000 \\\n"
    << "  --PatchMatchStereo.geom_consistency " << (geometric ? "true" : "false") << "\n"
    << "$COLMAP_EXE_PATH/colmap stereo_fusion \\\n"
    << "  --workspace_path . \\\n"
    << "  --workspace_format COLMAP \\\n"
    << "  --input_type " << type << " \\\n"
    << "  --output_path ./fused.ply\n"
    << "$COLMAP_EXE_PATH/colmap poisson_mesher \\\n"
    << "  --input_path ./fused.ply \\\n"
    << "  --output_path ./meshed-poisson.ply\n"
    << "$COLMAP_EXE_PATH/colmap delaunay_mesher \\\n"
    << "  --input_path . \\\n"
    << "  --input_type dense \\\n"
    << "  --output_path ./meshed-delaunay.ply\n";
  return s.str();
}

std::string JsonVector(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s << std::setprecision(10) << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return s.str();
}

}  // namespace

std::string GroundTruthJson(const std::vector<PinholeView>& views, const SurfaceSample& sample,
                            const std::vector<std::pair<std::string, std::string>>& header) {
  const double extent = sample.Extent();
  std::ostringstream s;
  s << std::setprecision(10) << "{\n";
  for (const auto& entry : header) s << "  \"" << entry.first << "\": " << entry.second << ",\n";
  s << "  \"extent\": " << extent << ",\n"
    << "  \"bbox_min\": " << JsonVector(sample.bbox_min) << ",\n"
    << "  \"bbox_max\": " << JsonVector(sample.bbox_max) << ",\n"
    << "  \"surface_sample_spacing\": " << kSurfaceSampleSpacing << ",\n"
    << "  \"num_surface_samples\": " << sample.points.size() << ",\n"
    << "  \"cloud_threshold_fraction_1\": " << kCloudThresholdFractions[0] << ",\n"
    << "  \"cloud_threshold_fraction_2\": " << kCloudThresholdFractions[1] << ",\n"
    << "  \"cloud_threshold_metres_1\": " << kCloudThresholdFractions[0] * extent << ",\n"
    << "  \"cloud_threshold_metres_2\": " << kCloudThresholdFractions[1] * extent << ",\n"
    << "  \"depth_relative_threshold_1\": " << kDepthRelativeThresholds[0] << ",\n"
    << "  \"depth_relative_threshold_2\": " << kDepthRelativeThresholds[1] << ",\n"
    << "  \"min_views_for_completeness\": " << kMinViewsForCompleteness << ",\n"
    << "  \"cameras\": [\n";
  for (size_t i = 0; i < views.size(); ++i) {
    const PinholeView& v = views[i];
    s << "    {\"name\": \"" << v.name << "\", \"width\": " << v.width
      << ", \"height\": " << v.height << ", \"fx\": " << v.fx << ", \"fy\": " << v.fy
      << ", \"cx\": " << v.cx << ", \"cy\": " << v.cy << ", \"center\": " << JsonVector(v.Center())
      << "}" << (i + 1 < views.size() ? "," : "") << "\n";
  }
  s << "  ]\n}\n";
  return s.str();
}

void WriteColmapWorkspace(const std::string& dir, const SparseModel& model,
                          const std::vector<RenderedView>& rendered) {
  const fs::path root(dir);
  std::string patch_match_cfg, fusion_cfg;
  for (size_t i = 0; i < model.images.size(); ++i) {
    const std::string& name = model.images[i].name;
    WritePng(root / "images" / name, rendered[i].image);
    patch_match_cfg += name + "\n__auto__, " + std::to_string(kNumPatchMatchSources) + "\n";
    fusion_cfg += name + "\n";
  }
  WriteSparseModelBinary(model, (root / "sparse").string());
  WriteText(root / "stereo" / "patch-match.cfg", patch_match_cfg);
  WriteText(root / "stereo" / "fusion.cfg", fusion_cfg);
  // COLMAP also creates the (empty) output folders.
  for (const char* sub : {"depth_maps", "normal_maps", "consistency_graphs"}) {
    fs::create_directories(root / "stereo" / sub);
  }
  WriteText(root / "run-colmap-geometric.sh", RunScript(true));
  WriteText(root / "run-colmap-photometric.sh", RunScript(false));
}

void WriteGroundTruth(const std::string& dir, const std::vector<PinholeView>& views,
                      const std::vector<RenderedView>& rendered, const SurfaceSample& sample,
                      const std::string& scene_json) {
  const fs::path gt = fs::path(dir) / "ground_truth";
  std::string names;
  for (size_t i = 0; i < views.size(); ++i) {
    const std::string& name = views[i].name;
    WriteDenseMap((gt / "depth_maps" / (name + ".bin")).string(), rendered[i].depth);
    WriteDenseMap((gt / "normal_maps" / (name + ".bin")).string(), rendered[i].normal);
    // "<name>.png" as COLMAP's fusion masks are named.
    WritePng(gt / "textureless" / (name + ".png"), rendered[i].textureless);
    names += name + "\n";
  }
  fs::create_directories(gt);
  WriteSurfacePly((gt / "surface.ply").string(), sample);
  WriteText(gt / "images.txt", names);
  WriteText(gt / "scene.json", scene_json);
}

void WriteIdealMasks(const std::string& dir, const std::vector<PinholeView>& views,
                     const std::vector<IdealMasks>& masks) {
  const std::string mask_dir = (fs::path(dir) / "masks").string();
  for (size_t i = 0; i < views.size(); ++i) {
    for (int level = 0; level < kNumIdealMaskLevels; ++level) {
      WritePng(MaskLayerPath(mask_dir, views[i].name, level), masks[i][level]);
    }
  }
}

}  // namespace scene
}  // namespace msp

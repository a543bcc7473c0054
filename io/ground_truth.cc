#include "io/ground_truth.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/errors.h"
#include "io/file_util.h"

namespace msp {
namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError("cannot read ground-truth file " + path);
  std::ostringstream s;
  s << file.rdbuf();
  return s.str();
}

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// The position just after the ':' that follows "key", or npos.
size_t FindJsonValue(const std::string& json, const std::string& key) {
  const std::string quoted = "\"" + key + "\"";
  const size_t pos = json.find(quoted);
  if (pos == std::string::npos) return std::string::npos;
  const size_t colon = json.find(':', pos + quoted.size());
  return colon == std::string::npos ? colon : colon + 1;
}

}  // namespace

std::string GroundTruthInfo::DepthMapPath(const std::string& name) const {
  return dir + "/depth_maps/" + name + ".bin";
}
std::string GroundTruthInfo::NormalMapPath(const std::string& name) const {
  return dir + "/normal_maps/" + name + ".bin";
}
std::string GroundTruthInfo::TexturelessPath(const std::string& name) const {
  return dir + "/textureless/" + name + ".png";
}
std::string GroundTruthInfo::SurfacePath() const { return dir + "/surface.ply"; }

std::string GroundTruthDir(const std::string& workspace, const std::string& dir) {
  return dir.empty() ? workspace + "/ground_truth" : dir;
}

bool FindJsonNumber(const std::string& json, const std::string& key, double* value) {
  const size_t pos = FindJsonValue(json, key);
  if (pos == std::string::npos) return false;
  const char* begin = json.c_str() + pos;
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin) return false;
  *value = v;
  return true;
}

bool FindJsonString(const std::string& json, const std::string& key, std::string* value) {
  const size_t pos = FindJsonValue(json, key);
  if (pos == std::string::npos) return false;
  const size_t open = json.find_first_not_of(" \t\r\n", pos);
  if (open == std::string::npos || json[open] != '"') return false;
  const size_t close = json.find('"', open + 1);
  if (close == std::string::npos) return false;
  *value = json.substr(open + 1, close - open - 1);
  return true;
}

GroundTruthInfo ReadGroundTruthInfo(const std::string& dir) {
  GroundTruthInfo info;
  info.dir = dir;
  std::istringstream names(ReadFile(dir + "/images.txt"));
  for (std::string line; std::getline(names, line);) {
    line = Trim(line);
    if (!line.empty()) info.image_names.push_back(line);
  }
  const std::string json_path = dir + "/scene.json";
  const std::string json = ReadFile(json_path);
  if (!FindJsonNumber(json, "extent", &info.extent) || !(info.extent > 0.0)) {
    throw InputError(json_path + ": missing or non-positive \"extent\"");
  }
  // Optional keys keep their defaults.
  FindJsonNumber(json, "cloud_threshold_fraction_1", &info.cloud_threshold_fractions[0]);
  FindJsonNumber(json, "cloud_threshold_fraction_2", &info.cloud_threshold_fractions[1]);
  FindJsonNumber(json, "depth_relative_threshold_1", &info.depth_relative_thresholds[0]);
  FindJsonNumber(json, "depth_relative_threshold_2", &info.depth_relative_thresholds[1]);
  FindJsonNumber(json, "absolute_threshold_metres_1", &info.absolute_thresholds_m[0]);
  FindJsonNumber(json, "absolute_threshold_metres_2", &info.absolute_thresholds_m[1]);
  double min_views = info.min_views_for_completeness;
  if (FindJsonNumber(json, "min_views_for_completeness", &min_views)) {
    info.min_views_for_completeness = static_cast<int>(min_views);
  }
  FindJsonString(json, "depth_source", &info.depth_source);
  FindJsonString(json, "normals_rule", &info.normals_rule);
  FindJsonString(json, "textureless_rule", &info.textureless_rule);
  info.has_normals = IsDirectory(dir + "/normal_maps");
  info.has_textureless = IsDirectory(dir + "/textureless");
  return info;
}

int NearestGroundTruthIndex(int index, int size, int gt_size) {
  const double scaled = static_cast<double>(index) * gt_size / size;
  return std::min(gt_size - 1, static_cast<int>(std::lround(scaled)));
}

}  // namespace msp

#include "io/mask_conversion.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "io/errors.h"
#include "io/file_util.h"
#include "io/mask_layers.h"

namespace msp {
namespace fs = std::filesystem;
namespace {

constexpr char kMetadataFile[] = "metadata.csv";

struct MaskFile {
  std::string path;
  std::string stem;
  long long area = -1;  // -1 = not given by metadata.csv
};

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) {
    while (!field.empty() && (field.back() == '\r' || field.back() == ' ')) field.pop_back();
    while (!field.empty() && field.front() == ' ') field.erase(0, 1);
    fields.push_back(field);
  }
  return fields;
}

// id -> area from metadata.csv (SAM's automatic mask generator writes
// id,area,bbox_x0,...). Without an area column, areas are counted instead.
std::map<std::string, long long> ReadMetadata(const std::string& path) {
  std::stringstream text(ReadFileToString(path));
  std::string line;
  if (!std::getline(text, line)) throw InputError(path + ": empty metadata file");
  const std::vector<std::string> header = SplitCsvLine(line);
  const auto id_it = std::find(header.begin(), header.end(), "id");
  if (id_it == header.end()) throw InputError(path + ": no `id` column in the header");
  const size_t id_col = id_it - header.begin();
  const auto area_it = std::find(header.begin(), header.end(), "area");
  const size_t area_col = area_it == header.end() ? header.size() : area_it - header.begin();
  std::map<std::string, long long> areas;
  int line_number = 1;
  while (std::getline(text, line)) {
    ++line_number;
    if (line.find_first_not_of(" \r") == std::string::npos) continue;
    const std::vector<std::string> fields = SplitCsvLine(line);
    if (fields.size() <= id_col) {
      throw InputError(path + ":" + std::to_string(line_number) + ": no id field");
    }
    long long area = -1;
    if (area_col < fields.size()) {
      try {
        area = std::stoll(fields[area_col]);
      } catch (const std::exception&) {
        throw InputError(path + ":" + std::to_string(line_number) + ": area `" + fields[area_col] +
                         "` is not an integer");
      }
    }
    areas[fields[id_col]] = area;
  }
  return areas;
}

cv::Mat ReadMask(const std::string& path) {
  cv::Mat mask;
  try {
    mask = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw InputError(path + ": cannot read mask: " + e.what());
  }
  if (mask.empty()) throw InputError(path + ": cannot read mask (corrupt file or not an image)");
  if (mask.channels() != 1) {
    throw InputError(path + ": mask has " + std::to_string(mask.channels()) +
                     " channels; binary masks are single-channel 0/255 PNGs");
  }
  return mask;
}

// Masks of a level folder, largest first (ties: file name).
std::vector<MaskFile> ListMasks(const std::string& level_dir) {
  std::vector<MaskFile> masks;
  for (const fs::directory_entry& entry : fs::directory_iterator(level_dir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".png") continue;
    masks.push_back(MaskFile{entry.path().string(), entry.path().stem().string(), -1});
  }
  const std::string metadata_path = JoinPaths(level_dir, kMetadataFile);
  if (IsFile(metadata_path)) {
    const std::map<std::string, long long> areas = ReadMetadata(metadata_path);
    for (const auto& [id, area] : areas) {
      const auto it =
          std::find_if(masks.begin(), masks.end(), [&](const MaskFile& m) { return m.stem == id; });
      if (it == masks.end()) {
        throw InputError(metadata_path + ": lists mask id " + id + " but " +
                         JoinPaths(level_dir, id + ".png") + " does not exist");
      }
      it->area = area;
    }
  }
  return masks;
}

}  // namespace

PaintedLevel PaintMaskFolder(const std::string& level_dir) {
  std::vector<MaskFile> masks = ListMasks(level_dir);
  if (masks.empty()) throw InputError(level_dir + ": no mask PNGs in this level folder");
  if (masks.size() > static_cast<size_t>(kMaxMasksPerLevel)) {
    throw InputError(level_dir + ": " + std::to_string(masks.size()) + " masks; at most " +
                     std::to_string(kMaxMasksPerLevel) + " fit 16-bit region ids");
  }
  std::vector<cv::Mat> images;
  images.reserve(masks.size());
  PaintedLevel level;
  for (MaskFile& mask : masks) {
    images.push_back(ReadMask(mask.path));
    const cv::Mat& image = images.back();
    if (images.size() == 1) {
      level.width = image.cols;
      level.height = image.rows;
    } else if (image.cols != level.width || image.rows != level.height) {
      throw InputError(mask.path + ": mask is " + std::to_string(image.cols) + "x" +
                       std::to_string(image.rows) + " but " + masks[0].path + " is " +
                       std::to_string(level.width) + "x" + std::to_string(level.height));
    }
    if (mask.area < 0) mask.area = cv::countNonZero(image);
  }
  std::vector<size_t> order(masks.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (masks[a].area != masks[b].area) return masks[a].area > masks[b].area;
    return masks[a].path < masks[b].path;
  });
  level.labels.assign(static_cast<size_t>(level.width) * level.height, 0);
  for (size_t rank = 0; rank < order.size(); ++rank) {
    const cv::Mat& image = images[order[rank]];
    const uint16_t id = static_cast<uint16_t>(rank + 1);
    cv::Mat inside = image != 0;  // 8-bit 0/255 whatever the mask's depth
    for (int row = 0; row < level.height; ++row) {
      const uint8_t* in = inside.ptr<uint8_t>(row);
      uint16_t* out = level.labels.data() + static_cast<size_t>(row) * level.width;
      for (int col = 0; col < level.width; ++col) {
        if (in[col]) out[col] = id;
      }
    }
  }
  return level;
}

std::vector<std::string> FindMaskImages(const std::string& input_dir) {
  if (!IsDirectory(input_dir)) throw InputError(input_dir + ": mask folder does not exist");
  std::vector<std::string> names;
  const fs::path root(input_dir);
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    if (!it->is_directory()) continue;
    if (IsDirectory((it->path() / "0").string())) {
      names.push_back(fs::relative(it->path(), root).generic_string());
      it.disable_recursion_pending();  // its children are level folders
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

int ConvertMaskImage(const std::string& input_dir, const std::string& image_name,
                     const std::string& output_dir) {
  const std::string image_dir = JoinPaths(input_dir, image_name);
  int num_levels = 0;
  while (IsDirectory(JoinPaths(image_dir, std::to_string(num_levels)))) ++num_levels;
  if (IsDirectory(JoinPaths(image_dir, std::to_string(num_levels + 1)))) {
    throw InputError(JoinPaths(image_dir, std::to_string(num_levels)) + ": level folder " +
                     std::to_string(num_levels) + " is missing but level " +
                     std::to_string(num_levels + 1) + " exists");
  }
  int width = 0, height = 0;
  for (int n = 0; n < num_levels; ++n) {
    const std::string level_dir = JoinPaths(image_dir, std::to_string(n));
    const PaintedLevel level = PaintMaskFolder(level_dir);
    if (n == 0) {
      width = level.width;
      height = level.height;
    } else if (level.width != width || level.height != height) {
      throw InputError(level_dir + ": masks are " + std::to_string(level.width) + "x" +
                       std::to_string(level.height) + " but level 0 is " + std::to_string(width) +
                       "x" + std::to_string(height));
    }
    const cv::Mat mat(level.height, level.width, CV_16UC1,
                      const_cast<uint16_t*>(level.labels.data()));
    std::vector<uchar> bytes;
    cv::imencode(".png", mat, bytes);
    WriteFileAtomic(MaskLayerPath(output_dir, image_name, n),
                    std::string(bytes.begin(), bytes.end()));
  }
  return num_levels;
}

int ConvertMasks(const std::string& input_dir, const std::string& output_dir, std::ostream* log) {
  const std::vector<std::string> names = FindMaskImages(input_dir);
  if (names.empty()) {
    throw InputError(input_dir +
                     ": no image folders with level folders found (expected "
                     "<input>/<image_name>/0/<id>.png)");
  }
  for (const std::string& name : names) {
    const int levels = ConvertMaskImage(input_dir, name, output_dir);
    if (log != nullptr) {
      *log << name << ": " << levels << " levels written to " << output_dir << "\n";
    }
  }
  return static_cast<int>(names.size());
}

}  // namespace msp

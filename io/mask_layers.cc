#include "io/mask_layers.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/prior/prior_limits.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/png_header.h"
#include "options/option_name.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

// Images named in one log line before it is shortened to a count.
constexpr size_t kMaxNamesInLog = 10;

constexpr char kLayoutHint[] =
    " (mask layers are single-channel 16-bit PNGs of region ids; see docs/segmentation_masks.md, "
    "msp_convert_masks writes them from SAM-style binary masks)";

std::string TypeName(const cv::Mat& image) {
  const std::string depth = image.depth() == CV_8U    ? "8-bit"
                            : image.depth() == CV_16U ? "16-bit"
                                                      : "non-integer";
  return depth + " " + std::to_string(image.channels()) + "-channel";
}

std::string NameList(const std::vector<std::string>& names) {
  std::string text;
  for (size_t i = 0; i < names.size() && i < kMaxNamesInLog; ++i) {
    text += (i ? ", " : "") + names[i];
  }
  if (names.size() > kMaxNamesInLog) {
    text += " and " + std::to_string(names.size() - kMaxNamesInLog) + " more";
  }
  return text;
}

[[noreturn]] void ThrowSizeMismatch(const std::string& path, uint64_t width, uint64_t height,
                                    const MaskImage& image) {
  throw InputError(path + ": mask layer is " + std::to_string(width) + "x" +
                   std::to_string(height) + " but its image " + image.name + " is " +
                   std::to_string(image.width) + "x" + std::to_string(image.height) +
                   " (masks must be made from the undistorted images)");
}

// The size in the PNG header must be the image's before the file is decoded
// (png_header.h).
void CheckPngHeader(const std::string& path, const MaskImage& image) {
  uint32_t width = 0, height = 0;
  if (!ReadPngSize(path, &width, &height)) {
    throw InputError(path + ": cannot read mask layer: not a PNG file" + kLayoutHint);
  }
  if (width != static_cast<uint32_t>(image.width) ||
      height != static_cast<uint32_t>(image.height)) {
    ThrowSizeMismatch(path, width, height, image);
  }
}

std::vector<int32_t> ReadLevel(const std::string& path, const MaskImage& image) {
  CheckPngHeader(path, image);
  cv::Mat mask;
  try {
    mask = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw InputError(path + ": cannot read mask layer: " + e.what());
  }
  if (mask.empty()) {
    throw InputError(path + ": cannot read mask layer (corrupt file or unsupported format)");
  }
  if (mask.depth() != CV_16U || mask.channels() != 1) {
    throw InputError(path + ": mask layer is a " + TypeName(mask) + " image" + kLayoutHint);
  }
  if (mask.cols != image.width || mask.rows != image.height) {
    ThrowSizeMismatch(path, mask.cols, mask.rows, image);
  }
  std::vector<int32_t> labels(static_cast<size_t>(mask.cols) * mask.rows);
  for (int row = 0; row < mask.rows; ++row) {
    const uint16_t* src = mask.ptr<uint16_t>(row);
    std::copy(src, src + mask.cols, labels.begin() + static_cast<size_t>(row) * mask.cols);
  }
  return labels;
}

}  // namespace

std::string ResolveMaskPath(const std::string& mask_path, const std::string& workspace_path) {
  return mask_path.empty() ? JoinPaths(workspace_path, "masks") : mask_path;
}

std::string MaskLayerPath(const std::string& mask_dir, const std::string& image_name, int level) {
  return JoinPaths(mask_dir, image_name + "." + std::to_string(level) + ".png");
}

int CountMaskLevels(const std::string& mask_dir, const std::string& image_name) {
  int count = 0;
  while (count <= core::kMaxLabelLayers && IsFile(MaskLayerPath(mask_dir, image_name, count))) {
    ++count;
  }
  if (count > core::kMaxLabelLayers) {
    throw InputError(MaskLayerPath(mask_dir, image_name, count - 1) + ": more than " +
                     std::to_string(core::kMaxLabelLayers) + " mask levels");
  }
  // A later level without this one is a gap, not the end of the layers.
  for (int later = count + 1; later <= core::kMaxLabelLayers; ++later) {
    if (IsFile(MaskLayerPath(mask_dir, image_name, later))) {
      throw InputError(MaskLayerPath(mask_dir, image_name, count) + ": mask level " +
                       std::to_string(count) + " is missing but level " + std::to_string(later) +
                       " exists (levels must be numbered 0, 1, ... without gaps)");
    }
  }
  return count;
}

LabelLayers ReadMaskLayers(const std::string& mask_dir, const MaskImage& image, int num_levels) {
  LabelLayers layers;
  layers.width = image.width;
  layers.height = image.height;
  for (int level = 0; level < num_levels; ++level) {
    layers.levels.push_back(ReadLevel(MaskLayerPath(mask_dir, image.name, level), image));
  }
  return ResampleNearest(layers, image.work_width, image.work_height);
}

std::vector<ImageLabelLayers> LoadMaskLayers(const std::string& mask_dir,
                                             const std::vector<MaskImage>& images,
                                             int expected_levels, std::ostream* log) {
  std::vector<int> counts(images.size(), 0);
  int first_with_layers = -1;
  if (IsDirectory(mask_dir)) {
    for (size_t i = 0; i < images.size(); ++i) {
      counts[i] = CountMaskLevels(mask_dir, images[i].name);
      if (counts[i] == 0) continue;
      if (first_with_layers < 0) {
        first_with_layers = static_cast<int>(i);
      } else if (counts[i] != counts[first_with_layers]) {
        const size_t fewer = counts[i] < counts[first_with_layers] ? i : first_with_layers;
        throw InputError(
            MaskLayerPath(mask_dir, images[fewer].name, counts[fewer]) + ": missing: image " +
            images[i].name + " has " + std::to_string(counts[i]) + " mask levels but " +
            images[first_with_layers].name + " has " + std::to_string(counts[first_with_layers]) +
            " (give every image the same levels, or none to use the embedded "
            "segmenter)");
      }
    }
  }
  std::vector<ImageLabelLayers> result(images.size());
  std::vector<std::string> fallback;
  for (size_t i = 0; i < images.size(); ++i) {
    if (counts[i] == 0) {
      fallback.push_back(images[i].name);
      continue;
    }
    result[i].source = LabelSource::kMaskFiles;
    result[i].layers = ReadMaskLayers(mask_dir, images[i], counts[i]);
  }
  if (log != nullptr) {
    const size_t with_files = images.size() - fallback.size();
    if (with_files > 0) {
      const int levels = counts[first_with_layers];
      *log << "Segmentation prior: " << levels << " mask levels from " << mask_dir << " for "
           << with_files << " images";
      if (levels != expected_levels) {
        *log << " (" << MSP_OPTION_FLAG_OF(MspStereoOptions, advanced_num_mask_levels) << " is "
             << expected_levels << "; the files decide)";
      }
      *log << "\n";
    }
    if (!fallback.empty()) {
      *log << "Segmentation prior: embedded segmenter (" << expected_levels << " levels) for "
           << fallback.size() << " images without mask layers in " << mask_dir << ": "
           << NameList(fallback) << "\n";
    }
  }
  return result;
}

}  // namespace msp

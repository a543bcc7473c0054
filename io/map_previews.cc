#include "io/map_previews.h"

#include <algorithm>
#include <cmath>

#include "core/patch_match/map_stage.h"
#include "io/dense_map_io.h"
#include "io/errors.h"
#include "io/file_util.h"
#include "io/prior_previews.h"

namespace msp {
namespace {

// Percentiles of the valid depths that bound the colour scale.
constexpr double kNearPercentile = 0.02;
constexpr double kFarPercentile = 0.98;

// The value of rank `fraction` in `values` (reordered), nearest rank.
float Percentile(std::vector<float>* values, double fraction) {
  const size_t k = static_cast<size_t>(std::lround(fraction * (values->size() - 1)));
  std::nth_element(values->begin(), values->begin() + k, values->end());
  return (*values)[k];
}

}  // namespace

std::string MapPreviewPath(const std::string& workspace_path, const std::string& image_name,
                           MapPreview preview) {
  constexpr const char* kSuffixes[] = {".depth.png", ".normal.png", ".error.png", ".stages.png"};
  return PreviewPath(workspace_path, image_name, kSuffixes[static_cast<int>(preview)]);
}

DepthRange RobustDepthRange(const DenseMap& depth) {
  std::vector<float> valid;
  for (float d : depth.data) {
    if (std::isfinite(d) && d > 0.0f) valid.push_back(d);
  }
  if (valid.empty()) return DepthRange{};
  const float near = Percentile(&valid, kNearPercentile);
  return DepthRange{near, Percentile(&valid, kFarPercentile)};
}

RgbImage DepthPreview(const DenseMap& depth) {
  const DepthRange range = RobustDepthRange(depth);
  RgbImage image(depth.width, depth.height);
  for (int row = 0; row < depth.height; ++row) {
    for (int col = 0; col < depth.width; ++col) {
      image.At(row, col) = DepthColor(depth.At(row, col), range);
    }
  }
  return image;
}

RgbImage NormalPreview(const DenseMap& normal) {
  RgbImage image(normal.width, normal.height);
  for (int row = 0; row < normal.height; ++row) {
    for (int col = 0; col < normal.width; ++col) {
      image.At(row, col) =
          NormalColor(normal.At(row, col, 0), normal.At(row, col, 1), normal.At(row, col, 2));
    }
  }
  return image;
}

RgbImage StagesPreview(const DenseMap& stages) {
  RgbImage image(stages.width, stages.height);
  for (int row = 0; row < stages.height; ++row) {
    for (int col = 0; col < stages.width; ++col) {
      Rgb color{0, 0, 0};  // no plane
      switch (static_cast<int>(stages.At(row, col, 0))) {
        case core::kStageKept:
          color = Rgb{200, 200, 200};
          break;
        case core::kStageOpenSky:
          color = Rgb{110, 170, 255};
          break;
        case core::kStageFilterAngle:
          color = Rgb{255, 210, 0};
          break;
        case core::kStageFilterPhotometric:
          color = Rgb{230, 50, 200};
          break;
        case core::kStageFilterGeometric:
          color = Rgb{230, 40, 40};
          break;
        case core::kStageFilterSeveral:
          color = Rgb{255, 120, 0};
          break;
        default:
          break;
      }
      image.At(row, col) = color;
    }
  }
  return image;
}

std::string StagesMapPath(const std::string& workspace_path, const std::string& image_name) {
  return PreviewPath(workspace_path, image_name, ".stages.bin");
}

void WriteStagesMap(const std::string& workspace_path, const std::string& image_name,
                    const DenseMap& stages) {
  WriteDenseMap(StagesMapPath(workspace_path, image_name), stages);
  WritePreviewPng(MapPreviewPath(workspace_path, image_name, MapPreview::kStages),
                  StagesPreview(stages));
}

RgbImage ErrorPreview(const DenseMap& depth, const DenseMap& gt_depth, const double thresholds[2],
                      bool zero_is_empty) {
  RgbImage image(depth.width, depth.height);
  for (int row = 0; row < depth.height; ++row) {
    const int gt_row = NearestGroundTruthIndex(row, depth.height, gt_depth.height);
    for (int col = 0; col < depth.width; ++col) {
      const int gt_col = NearestGroundTruthIndex(col, depth.width, gt_depth.width);
      image.At(row, col) = DepthErrorColor(ClassifyDepthError(
          depth.At(row, col), gt_depth.At(gt_row, gt_col), thresholds, zero_is_empty));
    }
  }
  return image;
}

void WriteMapPreviews(const std::string& workspace_path, const std::string& image_name,
                      const DenseMap& depth, const DenseMap& normal,
                      const GroundTruthInfo* ground_truth) {
  WritePreviewPng(MapPreviewPath(workspace_path, image_name, MapPreview::kDepth),
                  DepthPreview(depth));
  WritePreviewPng(MapPreviewPath(workspace_path, image_name, MapPreview::kNormal),
                  NormalPreview(normal));
  if (ground_truth == nullptr ||
      std::find(ground_truth->image_names.begin(), ground_truth->image_names.end(), image_name) ==
          ground_truth->image_names.end()) {
    return;
  }
  const std::string gt_path = ground_truth->DepthMapPath(image_name);
  const DenseMap gt_depth = ReadDenseMap(gt_path);
  if (gt_depth.channels != 1) throw InputError(gt_path + ": a depth map has 1 channel");
  WritePreviewPng(MapPreviewPath(workspace_path, image_name, MapPreview::kError),
                  ErrorPreview(depth, gt_depth, ground_truth->depth_relative_thresholds,
                               ground_truth->ZeroDepthIsEmpty()));
}

std::vector<std::pair<std::string, std::string>> ExistingPreviews(const std::string& workspace_path,
                                                                  const std::string& image_name) {
  const std::pair<std::string, std::string> all[] = {
      {"depth", MapPreviewPath(workspace_path, image_name, MapPreview::kDepth)},
      {"normal", MapPreviewPath(workspace_path, image_name, MapPreview::kNormal)},
      {"error", MapPreviewPath(workspace_path, image_name, MapPreview::kError)},
      {"stages", MapPreviewPath(workspace_path, image_name, MapPreview::kStages)},
      {"prior", PriorPreviewPath(workspace_path, image_name)}};
  std::vector<std::pair<std::string, std::string>> existing;
  for (const auto& preview : all) {
    if (IsFile(preview.second)) existing.push_back(preview);
  }
  return existing;
}

}  // namespace msp

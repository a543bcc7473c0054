#include "colmap_ext/prior_previews.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "colmap_ext/errors.h"
#include "colmap_ext/file_util.h"

namespace msp {
namespace {

// The image is dimmed so one-pixel edges stand out on bright surfaces.
constexpr float kImageBrightness = 0.6f;
constexpr float kMaxByte = 255.0f;

}  // namespace

std::string PriorPreviewPath(const std::string& workspace_path, const std::string& image_name) {
  return JoinPaths(JoinPaths(workspace_path, "stereo/prior_previews"), image_name + ".png");
}

void WritePriorPreview(const std::string& path, const DenseMap& color,
                       const std::vector<uint8_t>& aggregated_edges,
                       const std::vector<uint8_t>& refined_edges) {
  const size_t num_pixels = static_cast<size_t>(color.width) * color.height;
  if (color.channels != 3 || (!aggregated_edges.empty() && aggregated_edges.size() != num_pixels) ||
      (!refined_edges.empty() && refined_edges.size() != num_pixels)) {
    throw std::logic_error("WritePriorPreview: image and edge maps differ in size");
  }
  cv::Mat bgr(color.height, color.width, CV_8UC3);
  for (int row = 0; row < color.height; ++row) {
    cv::Vec3b* out = bgr.ptr<cv::Vec3b>(row);
    for (int col = 0; col < color.width; ++col) {
      const size_t i = static_cast<size_t>(row) * color.width + col;
      const bool aggregated = !aggregated_edges.empty() && aggregated_edges[i];
      const bool refined = !refined_edges.empty() && refined_edges[i];
      if (aggregated || refined) {  // red, green or yellow (BGR order)
        out[col] = cv::Vec3b(0, refined ? 255 : 0, aggregated ? 255 : 0);
        continue;
      }
      for (int c = 0; c < 3; ++c) {  // RGB planes -> BGR pixel
        const float v = kImageBrightness * kMaxByte * color.At(row, col, c);
        out[col][2 - c] = cv::saturate_cast<uint8_t>(v);
      }
    }
  }
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", bgr, bytes)) throw InputError(path + ": cannot encode preview PNG");
  WriteFileAtomic(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace msp

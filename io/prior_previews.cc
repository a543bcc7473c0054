#include "io/prior_previews.h"

#include <stdexcept>

#include "io/preview_image.h"

namespace msp {
namespace {

// The image is dimmed so one-pixel edges stand out on bright surfaces.
constexpr float kImageBrightness = 0.6f;

}  // namespace

std::string PriorPreviewPath(const std::string& workspace_path, const std::string& image_name) {
  return PreviewPath(workspace_path, image_name, ".png");
}

void WritePriorPreview(const std::string& path, const DenseMap& color,
                       const std::vector<uint8_t>& aggregated_edges,
                       const std::vector<uint8_t>& refined_edges) {
  const size_t num_pixels = static_cast<size_t>(color.width) * color.height;
  if (color.channels != 3 || (!aggregated_edges.empty() && aggregated_edges.size() != num_pixels) ||
      (!refined_edges.empty() && refined_edges.size() != num_pixels)) {
    throw std::logic_error("WritePriorPreview: image and edge maps differ in size");
  }
  RgbImage preview(color.width, color.height);
  for (int row = 0; row < color.height; ++row) {
    for (int col = 0; col < color.width; ++col) {
      const size_t i = static_cast<size_t>(row) * color.width + col;
      const bool aggregated = !aggregated_edges.empty() && aggregated_edges[i];
      const bool refined = !refined_edges.empty() && refined_edges[i];
      Rgb& out = preview.At(row, col);
      if (aggregated || refined) {  // red, green or yellow
        out = Rgb{static_cast<uint8_t>(aggregated ? 255 : 0),
                  static_cast<uint8_t>(refined ? 255 : 0), 0};
        continue;
      }
      out = Rgb{ToByte(kImageBrightness * color.At(row, col, 0)),
                ToByte(kImageBrightness * color.At(row, col, 1)),
                ToByte(kImageBrightness * color.At(row, col, 2))};
    }
  }
  WritePreviewPng(path, preview);
}

}  // namespace msp

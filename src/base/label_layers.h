// Multi-granularity label layers of one image (docs/method.md section 4.1: the
// mask maps M_1..M_N): per level a row-major map of region ids, level 0 the
// coarsest, 0 = unlabelled. Filled from mask files by io/mask_layers.h or by the
// embedded segmenter (multiscale_segmentation.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace msp {

struct LabelLayers {
  int width = 0;
  int height = 0;
  // levels[n][row * width + col], n = 0 coarsest.
  std::vector<std::vector<int32_t>> levels;

  int NumLevels() const { return static_cast<int>(levels.size()); }
  int32_t At(int level, int row, int col) const {
    return levels[level][static_cast<size_t>(row) * width + col];
  }
};

// Where an image's layers come from: user mask files, or the embedded
// segmenter (multiscale_segmentation.h) when the image has none.
enum class LabelSource { kMaskFiles, kEmbeddedSegmenter };

// The layers of one image and their source; `layers` is empty for
// kEmbeddedSegmenter until the segmenter has run.
struct ImageLabelLayers {
  LabelSource source = LabelSource::kEmbeddedSegmenter;
  LabelLayers layers;
};

// Nearest-neighbour resampling of a label map (labels must never blend): the
// output pixel (col, row) takes the input pixel under its centre,
// floor((col + 0.5) * width / new_width).
std::vector<int32_t> ResampleLabelsNearest(const std::vector<int32_t>& labels, int width,
                                           int height, int new_width, int new_height);

// Every level resampled to new_width x new_height.
LabelLayers ResampleNearest(const LabelLayers& layers, int new_width, int new_height);

}  // namespace msp

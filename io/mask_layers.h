// Reads the per-image segmentation mask layers of the prior (docs/method.md
// section 4.1: mask maps M_1..M_N): single-channel 16-bit PNGs of region
// ids, 0 = unlabelled, at <mask_path>/<image_name>.<level>.png with level 0
// the coarsest, the size of the undistorted image. Images without any layer
// fall back to the embedded segmenter. Layout: docs/segmentation_masks.md.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "base/label_layers.h"

namespace msp {

// One image whose layers are wanted.
struct MaskImage {
  std::string name;  // image name as in the sparse model, may hold sub-folders
  int width = 0;     // undistorted image size: the size every layer must have
  int height = 0;
  int work_width = 0;  // working resolution the layers are resampled to
  int work_height = 0;
};

// --MspStereo.mask_path, or <workspace>/masks when it is empty.
std::string ResolveMaskPath(const std::string& mask_path, const std::string& workspace_path);

// <mask_dir>/<image_name>.<level>.png
std::string MaskLayerPath(const std::string& mask_dir, const std::string& image_name, int level);

// Levels 0..n-1 present for `image_name`. Throws InputError naming the
// missing file when a level is absent but a later one exists, or when there
// are more than core::kMaxLabelLayers levels.
int CountMaskLevels(const std::string& mask_dir, const std::string& image_name);

// Reads levels 0..num_levels-1 of `image`, checks type and size, and
// resamples them (nearest neighbour) to the working resolution. Throws
// InputError naming the file when it is unreadable, not a single-channel
// 16-bit PNG, or not image.width x image.height.
LabelLayers ReadMaskLayers(const std::string& mask_dir, const MaskImage& image, int num_levels);

// The layers of every image: read from `mask_dir` where they exist, else
// marked kEmbeddedSegmenter (layers left empty). Every image with layers must
// have the same number of levels (InputError otherwise). Writes one summary
// line per source to `log` (may be null), naming the images that fall back;
// `expected_levels` (--MspStereo.advanced_num_mask_levels) is only compared and noted.
std::vector<ImageLabelLayers> LoadMaskLayers(const std::string& mask_dir,
                                             const std::vector<MaskImage>& images,
                                             int expected_levels, std::ostream* log);

}  // namespace msp

// Converts the output of SAM-family automatic mask generators into the label
// layers of the segmentation prior (msp_convert_masks). Input layout, per
// image and level, a folder of binary masks:
//   <input>/<image_name>/<level>/<id>.png     one 0/255 PNG per mask
//   <input>/<image_name>/<level>/metadata.csv optional: id,area,... columns
// Output: <output>/<image_name>.<level>.png, single-channel 16-bit region ids.
// Larger masks are painted first and smaller ones over them, so the finer
// region wins where masks overlap; pixels under no mask stay 0 (unlabelled).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace msp {

// Most masks one level can hold: ids are 16-bit and 0 means unlabelled.
constexpr int kMaxMasksPerLevel = 65535;

// A painted level: row-major region ids 1..N (N = number of masks painted,
// largest mask = 1), 0 = under no mask.
struct PaintedLevel {
  int width = 0;
  int height = 0;
  std::vector<uint16_t> labels;
};

// Paints the masks of one level folder. Areas come from metadata.csv where it
// lists the mask's id, else from the mask's pixel count; equal areas are
// ordered by file name. Throws InputError naming the file on an unreadable or
// colour mask, masks of different sizes, a metadata.csv without id column or
// naming a missing mask, an empty folder, or more than kMaxMasksPerLevel masks.
PaintedLevel PaintMaskFolder(const std::string& level_dir);

// Image names (relative paths below `input_dir`, '/'-separated) of the
// folders that hold a level folder "0", sorted.
std::vector<std::string> FindMaskImages(const std::string& input_dir);

// Converts every level of one image; returns the number of levels. Levels
// must be numbered 0, 1, ... without gaps and all have the same size.
int ConvertMaskImage(const std::string& input_dir, const std::string& image_name,
                     const std::string& output_dir);

// Converts every image under `input_dir`; one line per image to `log` (may be
// null). Returns the number of images. Throws InputError when there is none.
int ConvertMasks(const std::string& input_dir, const std::string& output_dir, std::ostream* log);

}  // namespace msp

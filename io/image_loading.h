// Reads one workspace image with OpenCV into the grey and colour planes the
// back-ends use, at the working resolution.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/dense_map.h"

namespace msp {

// The most pixels a workspace image may have (268 Mpx, beyond any camera's
// sensor): a camera larger than this in the sparse model is refused before
// its image is read, which would take 16 bytes a pixel as float planes.
constexpr uint64_t kMaxImagePixels = uint64_t{1} << 28;

// A workspace image as decoded: 8-bit BGR, row-major, pixel-interleaved.
struct DecodedImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> bgr;
};

// Reads `path` (PNG, JPEG, TIFF or BMP), checking that it is width x height
// (its header before it is decoded, so a header declaring a huge image
// allocates nothing: image_header.h). Throws InputError naming `path` when
// the file is unreadable, has the wrong size or its camera has more than
// kMaxImagePixels.
DecodedImage DecodeViewImage(const std::string& path, int width, int height);

// The planes the back-ends use from a decoded image: resized to
// new_width x new_height (cv::INTER_AREA) in float, `gray` (1 channel) and
// `color` (3 channels, RGB), each unless null, with values in [0, 1]. The
// same bytes give the same planes, so a colour image kept decoded in memory
// (3 bytes a pixel against the colour plane's 12) is converted again when
// needed.
void ConvertViewImage(const DecodedImage& image, int new_width, int new_height, DenseMap* gray,
                      DenseMap* color);

// DecodeViewImage, then ConvertViewImage.
void LoadViewImage(const std::string& path, int width, int height, int new_width, int new_height,
                   DenseMap* gray, DenseMap* color);

}  // namespace msp

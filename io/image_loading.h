// Reads one workspace image with OpenCV into the grey and colour planes the
// back-ends use, at the working resolution.
#pragma once

#include <cstdint>
#include <string>

#include "base/dense_map.h"

namespace msp {

// The most pixels a workspace image may have (268 Mpx, beyond any camera's
// sensor): a camera larger than this in the sparse model is refused before
// its image is read, which would take 16 bytes a pixel as float planes.
constexpr uint64_t kMaxImagePixels = uint64_t{1} << 28;

// Loads `path` (PNG, JPEG, TIFF or BMP), checks that it is width x height (its
// header before it is decoded, so a header declaring a huge image allocates
// nothing: image_header.h), resizes it to new_width x new_height (cv::INTER_AREA) and fills
// `gray` (1 channel) and `color` (3 channels, RGB) with values in [0, 1]. Throws InputError naming
// `path` when the file is unreadable, has the wrong size or its camera has
// more than kMaxImagePixels.
void LoadViewImage(const std::string& path, int width, int height, int new_width, int new_height,
                   DenseMap* gray, DenseMap* color);

}  // namespace msp

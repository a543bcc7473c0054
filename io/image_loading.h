// Reads one workspace image with OpenCV into the grey and colour planes the
// back-ends use, at the working resolution.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "base/dense_map.h"

namespace msp {

// The most pixels a workspace image may have (268 Mpx, beyond any camera's
// sensor): a camera larger than this in the sparse model is refused before
// its image is read, which would take 16 bytes a pixel as float planes.
constexpr uint64_t kMaxImagePixels = uint64_t{1} << 28;

// Reads `path` (PNG, JPEG, TIFF or BMP) as 8-bit BGR, checking that it is
// width x height (its header before it is decoded, so a header declaring a
// huge image allocates nothing: image_header.h). Throws InputError naming
// `path` when the file is unreadable, has the wrong size or its camera has
// more than kMaxImagePixels.
cv::Mat DecodeViewImage(const std::string& path, int width, int height);

// The planes the back-ends use from a decoded image: resized to
// new_width x new_height (cv::INTER_AREA) in float, `gray` (1 channel) and,
// unless `color` is null, `color` (3 channels, RGB), with values in [0, 1].
// The same bytes give the same planes, so an image kept decoded in memory
// (3 bytes a pixel against the planes' 16) is converted again when needed.
void ConvertViewImage(const cv::Mat& bgr, int new_width, int new_height, DenseMap* gray,
                      DenseMap* color);

// DecodeViewImage, then ConvertViewImage.
void LoadViewImage(const std::string& path, int width, int height, int new_width, int new_height,
                   DenseMap* gray, DenseMap* color);

}  // namespace msp

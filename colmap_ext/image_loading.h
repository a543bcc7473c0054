// Reads one workspace image with OpenCV into the grey and colour planes the
// back-ends use, at the working resolution.
#pragma once

#include <string>

#include "base/dense_map.h"

namespace msp {

// Loads `path`, checks that it is width x height, resizes it to
// new_width x new_height (cv::INTER_AREA) and fills `gray` (1 channel) and
// `color` (3 channels, RGB) with values in [0, 1]. Throws InputError naming
// `path` when the file is unreadable or has the wrong size.
void LoadViewImage(const std::string& path, int width, int height, int new_width, int new_height,
                   DenseMap* gray, DenseMap* color);

}  // namespace msp

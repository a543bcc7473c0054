// Image files (PNG masks, mask layers, workspace images) written with OpenCV.
#pragma once

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "tests/support/files.h"

namespace msp {
namespace test {

// Writes `image` to `path` (format from the extension), creating its parent folders.
inline void WriteImage(const std::string& path, const cv::Mat& image) {
  CreateParentFolders(path);
  ASSERT_TRUE(cv::imwrite(path, image)) << path;
}

}  // namespace test
}  // namespace msp

// Image files (PNG masks, mask layers, workspace images) written with OpenCV.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

namespace msp {
namespace test {

// Writes `image` to `path` (format from the extension), creating its parent folders.
inline void WriteImage(const std::string& path, const cv::Mat& image) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  ASSERT_TRUE(cv::imwrite(path, image)) << path;
}

}  // namespace test
}  // namespace msp

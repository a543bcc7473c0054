#include "tools/rgbd/depth_png.h"

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/errors.h"
#include "io/png_header.h"

namespace msp {
namespace rgbd {
namespace {

std::string Size(uint64_t width, uint64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

DenseMap ReadDepthPng(const std::string& path, int width, int height, double units_per_metre) {
  uint32_t png_width = 0, png_height = 0;
  if (!ReadPngSize(path, &png_width, &png_height)) {
    throw InputError(path + ": cannot read depth: not a PNG file");
  }
  if (png_width != static_cast<uint32_t>(width) || png_height != static_cast<uint32_t>(height)) {
    throw InputError(path + ": depth map is " + Size(png_width, png_height) + " but its image is " +
                     Size(width, height) +
                     " (the depth must be registered to the colour image, pixel for pixel)");
  }
  cv::Mat raw;
  try {
    raw = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    throw InputError(path + ": cannot read depth: " + e.what());
  }
  if (raw.empty()) throw InputError(path + ": cannot read depth (corrupt PNG)");
  if (raw.depth() != CV_16U || raw.channels() != 1) {
    throw InputError(path + ": depth must be a single-channel 16-bit PNG, not " +
                     std::to_string(raw.elemSize1() * 8) + "-bit with " +
                     std::to_string(raw.channels()) + " channel(s)");
  }
  DenseMap depth(width, height, 1);
  const double metres_per_unit = 1.0 / units_per_metre;
  for (int row = 0; row < height; ++row) {
    const uint16_t* src = raw.ptr<uint16_t>(row);
    for (int col = 0; col < width; ++col) {
      depth.At(row, col) = static_cast<float>(src[col] * metres_per_unit);
    }
  }
  return depth;
}

}  // namespace rgbd
}  // namespace msp

#include "io/image_loading.h"

#include <cstdint>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "io/errors.h"
#include "io/image_header.h"

namespace msp {
namespace {

constexpr double kInv255 = 1.0 / 255.0;

// Each byte's value in [0, 1] as convertTo(CV_32F, kInv255) gives it: the
// conversion is per value, so a table gives the same floats.
const std::vector<float>& UnitOfByte() {
  static const std::vector<float> table = [] {
    cv::Mat bytes(1, 256, CV_8UC1);
    for (int b = 0; b < 256; ++b) bytes.at<uint8_t>(0, b) = static_cast<uint8_t>(b);
    cv::Mat values;
    bytes.convertTo(values, CV_32F, kInv255);
    return std::vector<float>(values.ptr<float>(), values.ptr<float>() + 256);
  }();
  return table;
}

// The RGB planes of an image at its own size, straight from its bytes: no
// float BGR image between, which at 1536x1024 is 19 MB written and read
// again each time a problem's reference needs its colour.
DenseMap ColorPlanes(const DecodedImage& image) {
  const std::vector<float>& unit = UnitOfByte();
  DenseMap color(image.width, image.height, 3);
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  for (int c = 0; c < 3; ++c) {
    float* out = color.Plane(c);
    const uint8_t* in = image.bgr.data() + (2 - c);  // BGR -> RGB
    for (size_t i = 0; i < pixels; ++i) out[i] = unit[in[3 * i]];
  }
  return color;
}

void CopyPlane(const cv::Mat& plane, float* out) {
  for (int row = 0; row < plane.rows; ++row) {
    const float* src = plane.ptr<float>(row);
    std::copy(src, src + plane.cols, out + static_cast<size_t>(row) * plane.cols);
  }
}

[[noreturn]] void ThrowSizeMismatch(const std::string& path, uint64_t image_width,
                                    uint64_t image_height, int width, int height) {
  throw InputError(path + ": image is " + std::to_string(image_width) + "x" +
                   std::to_string(image_height) + " but its camera in the sparse model is " +
                   std::to_string(width) + "x" + std::to_string(height) +
                   " (use the images written by `colmap image_undistorter`)");
}

// Before anything is decoded: the camera may not be larger than
// kMaxImagePixels, the file must be of a format image_header.h knows, and its
// header must declare the camera's size, since the decoder allocates whatever
// the header declares (a 45-byte PNG may declare 40000x20000).
void CheckImageHeader(const std::string& path, int width, int height) {
  if (static_cast<uint64_t>(width) * static_cast<uint64_t>(height) > kMaxImagePixels) {
    throw InputError(path + ": its camera in the sparse model is " + std::to_string(width) + "x" +
                     std::to_string(height) + ", more than the " + std::to_string(kMaxImagePixels) +
                     " pixels an image may have");
  }
  if (!std::ifstream(path, std::ios::binary)) {
    throw InputError(path + ": cannot read image: no such file, or not readable");
  }
  const ImageFormat format = DetectImageFormat(path);
  if (format == ImageFormat::kUnknown) {
    throw InputError(path + ": cannot read image: not a PNG, JPEG, TIFF or BMP file");
  }
  uint32_t header_width = 0, header_height = 0;
  if (!ReadImageSize(path, format, &header_width, &header_height)) {
    throw InputError(path + ": cannot read image: corrupt " + ImageFormatName(format) + " header");
  }
  if (header_width != static_cast<uint32_t>(width) ||
      header_height != static_cast<uint32_t>(height)) {
    ThrowSizeMismatch(path, header_width, header_height, width, height);
  }
}

}  // namespace

DecodedImage DecodeViewImage(const std::string& path, int width, int height) {
  CheckImageHeader(path, width, height);
  cv::Mat bgr;
  try {
    bgr = cv::imread(path, cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    throw InputError(path + ": cannot read image: " + e.what());
  }
  if (bgr.empty()) {
    throw InputError(path + ": cannot read image (corrupt file or unsupported format)");
  }
  if (bgr.cols != width || bgr.rows != height) {
    ThrowSizeMismatch(path, bgr.cols, bgr.rows, width, height);
  }
  DecodedImage image;
  image.width = width;
  image.height = height;
  image.bgr.resize(static_cast<size_t>(width) * height * 3);
  cv::Mat into(height, width, CV_8UC3, image.bgr.data());
  bgr.copyTo(into);  // same size and type: writes image.bgr
  return image;
}

void ConvertViewImage(const DecodedImage& image, int new_width, int new_height, DenseMap* gray,
                      DenseMap* color) {
  const bool resized = new_width != image.width || new_height != image.height;
  if (color != nullptr && !resized) *color = ColorPlanes(image);
  const bool color_from_float = color != nullptr && resized;
  if (gray == nullptr && !color_from_float) return;

  const cv::Mat bgr(image.height, image.width, CV_8UC3, const_cast<uint8_t*>(image.bgr.data()));
  // Convert to float before resizing so neither step rounds to 8 bits.
  cv::Mat bgr_float;
  bgr.convertTo(bgr_float, CV_32FC3, kInv255);
  if (resized) {
    cv::Mat smaller;
    cv::resize(bgr_float, smaller, cv::Size(new_width, new_height), 0.0, 0.0, cv::INTER_AREA);
    bgr_float = smaller;
  }
  if (gray != nullptr) {
    cv::Mat gray_float;
    cv::cvtColor(bgr_float, gray_float, cv::COLOR_BGR2GRAY);
    *gray = DenseMap(new_width, new_height, 1);
    CopyPlane(gray_float, gray->Plane(0));
  }
  if (!color_from_float) return;
  std::vector<cv::Mat> bgr_planes;
  cv::split(bgr_float, bgr_planes);
  *color = DenseMap(new_width, new_height, 3);
  for (int c = 0; c < 3; ++c) CopyPlane(bgr_planes[2 - c], color->Plane(c));  // BGR -> RGB
}

void LoadViewImage(const std::string& path, int width, int height, int new_width, int new_height,
                   DenseMap* gray, DenseMap* color) {
  ConvertViewImage(DecodeViewImage(path, width, height), new_width, new_height, gray, color);
}

}  // namespace msp

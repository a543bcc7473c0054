#include "io/preview_image.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/errors.h"
#include "io/file_util.h"

namespace msp {
namespace {

constexpr float kMaxByte = 255.0f;

}  // namespace

uint8_t ToByte(float fraction) { return cv::saturate_cast<uint8_t>(kMaxByte * fraction); }

std::string PreviewPath(const std::string& workspace_path, const std::string& image_name,
                        const std::string& suffix) {
  return JoinPaths(JoinPaths(workspace_path, "stereo/prior_previews"), image_name + suffix);
}

void WritePreviewPng(const std::string& path, const RgbImage& image) {
  cv::Mat bgr(image.height, image.width, CV_8UC3);
  for (int row = 0; row < image.height; ++row) {
    cv::Vec3b* out = bgr.ptr<cv::Vec3b>(row);
    for (int col = 0; col < image.width; ++col) {
      const Rgb& p = image.At(row, col);
      out[col] = cv::Vec3b(p.b, p.g, p.r);
    }
  }
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", bgr, bytes)) throw InputError(path + ": cannot encode preview PNG");
  WriteFileAtomic(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace msp

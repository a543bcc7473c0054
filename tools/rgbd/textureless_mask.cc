#include "tools/rgbd/textureless_mask.h"

#include <opencv2/imgproc.hpp>

namespace msp {
namespace rgbd {

cv::Mat TexturelessMask(const cv::Mat& image) {
  cv::Mat grey;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  } else {
    grey = image;
  }
  cv::Mat g, mean, mean_sq;
  grey.convertTo(g, CV_64F);
  const int side = 2 * kTexturelessWindowRadius + 1;
  // Windows past the border repeat the border's pixels (no texture there).
  cv::blur(g, mean, cv::Size(side, side), cv::Point(-1, -1), cv::BORDER_REPLICATE);
  cv::blur(g.mul(g), mean_sq, cv::Size(side, side), cv::Point(-1, -1), cv::BORDER_REPLICATE);
  const cv::Mat variance = mean_sq - mean.mul(mean);
  cv::Mat mask = variance < kTexturelessStdDev * kTexturelessStdDev;
  return mask;
}

}  // namespace rgbd
}  // namespace msp

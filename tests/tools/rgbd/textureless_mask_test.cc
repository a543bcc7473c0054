#include "tools/rgbd/textureless_mask.h"

#include <gtest/gtest.h>

namespace msp {
namespace rgbd {
namespace {

// Left half flat grey with +-1 level of noise, right half a checkerboard of
// 2-pixel squares 40 levels apart.
cv::Mat HalfFlatHalfTextured() {
  cv::Mat image(40, 80, CV_8UC3);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const int v = c < 40 ? 120 + ((r + c) % 3) - 1 : (((r / 2) + (c / 2)) % 2 ? 100 : 140);
      image.at<cv::Vec3b>(r, c) = cv::Vec3b(v, v, v);
    }
  }
  return image;
}

TEST(TexturelessMask, FlatHalfIsTexturelessTexturedHalfIsNot) {
  const cv::Mat mask = TexturelessMask(HalfFlatHalfTextured());
  ASSERT_EQ(mask.type(), CV_8UC1);
  EXPECT_EQ(mask.at<uint8_t>(20, 10), 255);
  EXPECT_EQ(mask.at<uint8_t>(0, 0), 255);  // the border repeats its pixels
  EXPECT_EQ(mask.at<uint8_t>(20, 60), 0);
  // A window reaching kTexturelessWindowRadius into the checkerboard is not
  // textureless; one just short of it is.
  EXPECT_EQ(mask.at<uint8_t>(20, 40 - kTexturelessWindowRadius), 0);
  EXPECT_EQ(mask.at<uint8_t>(20, 40 - kTexturelessWindowRadius - 1), 255);
}

}  // namespace
}  // namespace rgbd
}  // namespace msp

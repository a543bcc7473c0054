#include "io/prior_previews.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/temp_dir.h"

namespace msp {
namespace {

TEST(PriorPreviews, EdgesAreDrawnInTheirColoursOverTheDimmedImage) {
  test::TempDir dir;
  DenseMap color(4, 2, 3, 1.0f);  // white
  const std::vector<uint8_t> aggregated = {1, 1, 0, 0, 0, 0, 0, 0};
  const std::vector<uint8_t> refined = {0, 1, 1, 0, 0, 0, 0, 0};
  const std::string path = PriorPreviewPath(dir.path(), "sub/a.jpg");
  EXPECT_EQ(path, dir.path() + "/stereo/prior_previews/sub/a.jpg.png");
  WritePriorPreview(path, color, aggregated, refined);
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  ASSERT_EQ(image.cols, 4);
  ASSERT_EQ(image.rows, 2);
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 255));      // aggregated only: red
  EXPECT_EQ(image.at<cv::Vec3b>(0, 1), cv::Vec3b(0, 255, 255));    // both: yellow
  EXPECT_EQ(image.at<cv::Vec3b>(0, 2), cv::Vec3b(0, 255, 0));      // refined only: green
  EXPECT_EQ(image.at<cv::Vec3b>(1, 3), cv::Vec3b(153, 153, 153));  // dimmed white
  WritePriorPreview(path, color, {}, {});                          // no edges at all
}

}  // namespace
}  // namespace msp

#include "tools/rgbd/depth_png.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace rgbd {
namespace {

TEST(ReadDepthPng, ScalesUnitsToMetresAndKeepsZeros) {
  const test::TempDir dir;
  cv::Mat png(2, 3, CV_16UC1, cv::Scalar(0));
  png.at<uint16_t>(0, 1) = 1500;
  png.at<uint16_t>(1, 2) = 65535;
  ASSERT_TRUE(cv::imwrite(dir / "d.png", png));
  const DenseMap depth = ReadDepthPng(dir / "d.png", 3, 2, 1000.0);
  EXPECT_EQ(depth.At(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(depth.At(0, 1), 1.5f);
  EXPECT_FLOAT_EQ(depth.At(1, 2), 65.535f);
  EXPECT_FLOAT_EQ(ReadDepthPng(dir / "d.png", 3, 2, 5000.0).At(0, 1), 0.3f);
}

TEST(ReadDepthPng, RejectsWhatIsNotARegisteredSixteenBitMap) {
  const test::TempDir dir;
  ASSERT_TRUE(cv::imwrite(dir / "rgb.png", cv::Mat(2, 3, CV_8UC3, cv::Scalar(1, 2, 3))));
  ASSERT_TRUE(cv::imwrite(dir / "d.png", cv::Mat(2, 3, CV_16UC1, cv::Scalar(7))));
  // A valid header whose body is cut off.
  test::WriteRaw(dir / "cut.png", test::ReadRaw(dir / "d.png").substr(0, 40));
  test::WriteRaw(dir / "text.png", "not an image");
  const struct {
    const char* file;
    int width;
    const char* expected;
  } cases[] = {
      {"rgb.png", 3, "single-channel 16-bit PNG, not 8-bit with 3 channel(s)"},
      {"d.png", 4, "depth map is 3x2 but its image is 4x2"},
      {"text.png", 3, "not a PNG file"},
      {"missing.png", 3, "not a PNG file"},
      {"cut.png", 3, "cannot read depth"},
  };
  for (const auto& c : cases) {
    const std::string message =
        test::InputErrorMessage([&] { ReadDepthPng(dir / c.file, c.width, 2, 1000.0); });
    EXPECT_NE(message.find(c.file), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace rgbd
}  // namespace msp

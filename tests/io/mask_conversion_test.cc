#include "io/mask_conversion.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <sstream>

#include "io/mask_layers.h"
#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/image_files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;
using test::TempDir;
using test::WriteImage;

constexpr int kWidth = 10;
constexpr int kHeight = 8;

// A 0/255 mask of the rectangle [col0, col1) x [row0, row1).
cv::Mat Rect(int col0, int row0, int col1, int row1, int width = kWidth, int height = kHeight) {
  cv::Mat mask = cv::Mat::zeros(height, width, CV_8UC1);
  mask(cv::Range(row0, row1), cv::Range(col0, col1)).setTo(255);
  return mask;
}

TEST(MaskConversion, SmallerMasksArePaintedOverLargerOnes) {
  TempDir dir;
  const std::string level = dir / "a.jpg/0";
  WriteImage(level + "/0.png", Rect(4, 2, 6, 4));   // small, inside the big one
  WriteImage(level + "/1.png", Rect(0, 0, 8, 8));   // big
  WriteImage(level + "/2.png", Rect(8, 0, 10, 3));  // medium, elsewhere
  const PaintedLevel painted = PaintMaskFolder(level);
  ASSERT_EQ(painted.width, kWidth);
  ASSERT_EQ(painted.height, kHeight);
  auto at = [&](int col, int row) { return painted.labels[row * kWidth + col]; };
  EXPECT_EQ(at(0, 0), 1);  // largest mask = id 1
  EXPECT_EQ(at(5, 3), 3);  // the small mask wins over the big one
  EXPECT_EQ(at(9, 0), 2);
  EXPECT_EQ(at(9, 5), 0);  // under no mask: unlabelled
}

TEST(MaskConversion, MetadataAreasDecideTheOrder) {
  TempDir dir;
  const std::string level = dir / "a.jpg/0";
  WriteImage(level + "/0.png", Rect(0, 0, 6, 6));
  WriteImage(level + "/1.png", Rect(3, 3, 9, 8));
  // The metadata claims mask 1 is larger: it is painted first, 0 over it.
  test::WriteRaw(level + "/metadata.csv",
                 "id,area,bbox_x0,bbox_y0,bbox_w,bbox_h,predicted_iou\n0,36,0,0,6,6,0.9\n"
                 "1,100,3,3,6,5,0.9\n");
  const PaintedLevel painted = PaintMaskFolder(level);
  EXPECT_EQ(painted.labels[4 * kWidth + 4], 2);  // overlap: mask 0 (id 2) on top
  EXPECT_EQ(painted.labels[7 * kWidth + 8], 1);
}

TEST(MaskConversion, ConvertsATreeIntoLayersTheReaderAccepts) {
  TempDir in, out;
  for (const std::string name : {"a.jpg", "sub/b.png"}) {
    WriteImage(in / (name + "/0/0.png"), Rect(0, 0, 10, 8));
    WriteImage(in / (name + "/1/0.png"), Rect(0, 0, 5, 8));
    WriteImage(in / (name + "/1/1.png"), Rect(5, 0, 10, 8));
    WriteImage(in / (name + "/2/7.png"), Rect(2, 2, 4, 4));
  }
  EXPECT_EQ(FindMaskImages(in.path()), (std::vector<std::string>{"a.jpg", "sub/b.png"}));
  std::ostringstream log;
  EXPECT_EQ(ConvertMasks(in.path(), out.path(), &log), 2);
  const MaskImage image{"sub/b.png", kWidth, kHeight, kWidth, kHeight};
  ASSERT_EQ(CountMaskLevels(out.path(), "sub/b.png"), 3);
  const LabelLayers layers = ReadMaskLayers(out.path(), image, 3);
  EXPECT_EQ(layers.levels[0], std::vector<int32_t>(kWidth * kHeight, 1));
  EXPECT_NE(layers.At(1, 0, 0), layers.At(1, 0, 9));
  EXPECT_EQ(layers.At(2, 3, 3), 1);
  EXPECT_EQ(layers.At(2, 0, 0), 0);
}

TEST(MaskConversion, BadInputsNameTheFile) {
  TempDir dir;
  const std::string level = dir / "a.jpg/0";
  WriteImage(level + "/0.png", Rect(0, 0, 4, 4));
  WriteImage(level + "/1.png", Rect(0, 0, 4, 4, kWidth + 2, kHeight));
  std::string message = InputErrorMessage([&] { PaintMaskFolder(level); });
  EXPECT_NE(message.find(level + "/1.png: mask is 12x8"), std::string::npos) << message;

  const std::string colour_level = dir / "c.jpg/0";
  cv::Mat colour(kHeight, kWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  WriteImage(colour_level + "/0.png", colour);
  message = InputErrorMessage([&] { PaintMaskFolder(colour_level); });
  EXPECT_NE(message.find(colour_level + "/0.png: mask has 3 channels"), std::string::npos)
      << message;

  const std::string meta_level = dir / "m.jpg/0";
  WriteImage(meta_level + "/0.png", Rect(0, 0, 4, 4));
  test::WriteRaw(meta_level + "/metadata.csv", "id,area\n0,16\n5,20\n");
  message = InputErrorMessage([&] { PaintMaskFolder(meta_level); });
  EXPECT_NE(message.find("lists mask id 5 but " + meta_level + "/5.png does not exist"),
            std::string::npos)
      << message;

  const std::string gap = dir / "g.jpg";
  WriteImage(gap + "/0/0.png", Rect(0, 0, 4, 4));
  WriteImage(gap + "/2/0.png", Rect(0, 0, 4, 4));
  message = InputErrorMessage([&] { ConvertMaskImage(dir.path(), "g.jpg", dir / "out"); });
  EXPECT_NE(message.find(gap + "/1: level folder 1 is missing"), std::string::npos) << message;

  message = InputErrorMessage([&] { ConvertMasks(dir / "nothing", dir / "out", nullptr); });
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

}  // namespace
}  // namespace msp

#include "io/mask_layers.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <sstream>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/image_files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;
using test::TempDir;
using test::WriteImage;

constexpr int kWidth = 8;
constexpr int kHeight = 6;

// A 16-bit layer with region id 1 left of `split` and 2 from it on.
cv::Mat Layer(int split, int width = kWidth, int height = kHeight) {
  cv::Mat mat(height, width, CV_16UC1);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) mat.at<uint16_t>(row, col) = col < split ? 1 : 2;
  }
  return mat;
}

// Levels 0 .. num_levels - 1 of image `name` under `mask_path`, each split at column 4.
void WriteLayers(const std::string& mask_path, const std::string& name, int num_levels) {
  for (int level = 0; level < num_levels; ++level) {
    WriteImage(MaskLayerPath(mask_path, name, level), Layer(4));
  }
}

MaskImage Image(const std::string& name, int work_width = kWidth, int work_height = kHeight) {
  return MaskImage{name, kWidth, kHeight, work_width, work_height};
}

TEST(MaskLayers, PathsFollowTheDocumentedNaming) {
  EXPECT_EQ(ResolveMaskPath("", "/ws"), "/ws/masks");
  EXPECT_EQ(ResolveMaskPath("/elsewhere", "/ws"), "/elsewhere");
  EXPECT_EQ(MaskLayerPath("/ws/masks", "sub/a.jpg", 2), "/ws/masks/sub/a.jpg.2.png");
}

TEST(MaskLayers, ReadsEveryLevelAndResamplesToTheWorkingSize) {
  TempDir dir;
  for (int level = 0; level < 3; ++level) {
    WriteImage(MaskLayerPath(dir.path(), "sub/a.jpg", level), Layer(2 + 2 * level));
  }
  EXPECT_EQ(CountMaskLevels(dir.path(), "sub/a.jpg"), 3);
  const LabelLayers layers = ReadMaskLayers(dir.path(), Image("sub/a.jpg", 4, 3), 3);
  ASSERT_EQ(layers.NumLevels(), 3);
  EXPECT_EQ(layers.width, 4);
  EXPECT_EQ(layers.height, 3);
  // Level 2 splits at column 6 of 8 -> column 3 of 4 (nearest neighbour).
  EXPECT_EQ(layers.levels[2], (std::vector<int32_t>{1, 1, 1, 2, 1, 1, 1, 2, 1, 1, 1, 2}));
  EXPECT_EQ(layers.At(0, 0, 0), 1);
  EXPECT_EQ(layers.At(0, 0, 1), 2);
}

TEST(MaskLayers, ImagesWithoutLayersFallBackAndTheLogSaysSo) {
  TempDir dir;
  WriteLayers(dir.path(), "a.jpg", 3);
  std::ostringstream log;
  const std::vector<ImageLabelLayers> result =
      LoadMaskLayers(dir.path(), {Image("a.jpg"), Image("b.jpg")}, 3, &log);
  ASSERT_EQ(result.size(), 2u);
  EXPECT_EQ(result[0].source, LabelSource::kMaskFiles);
  EXPECT_EQ(result[0].layers.NumLevels(), 3);
  EXPECT_EQ(result[1].source, LabelSource::kEmbeddedSegmenter);
  EXPECT_EQ(result[1].layers.NumLevels(), 0);
  EXPECT_NE(log.str().find("3 mask levels from " + dir.path() + " for 1 images"), std::string::npos)
      << log.str();
  EXPECT_NE(log.str().find("embedded segmenter (3 levels) for 1 images"), std::string::npos);
  EXPECT_NE(log.str().find("b.jpg"), std::string::npos);
}

TEST(MaskLayers, NoMaskFolderMeansEmbeddedForAll) {
  TempDir dir;
  std::ostringstream log;
  const std::vector<ImageLabelLayers> result =
      LoadMaskLayers(dir / "missing", {Image("a.jpg")}, 3, &log);
  EXPECT_EQ(result[0].source, LabelSource::kEmbeddedSegmenter);
  EXPECT_NE(log.str().find("embedded segmenter"), std::string::npos);
}

TEST(MaskLayers, AnyNumberOfLevelsIsAcceptedAndNoted) {
  TempDir dir;
  WriteLayers(dir.path(), "a.jpg", 5);
  std::ostringstream log;
  const std::vector<ImageLabelLayers> result =
      LoadMaskLayers(dir.path(), {Image("a.jpg")}, 3, &log);
  EXPECT_EQ(result[0].layers.NumLevels(), 5);
  EXPECT_NE(log.str().find("num_mask_levels is 3"), std::string::npos) << log.str();
}

TEST(MaskLayers, WrongSizeNamesTheFile) {
  TempDir dir;
  const std::string path = MaskLayerPath(dir.path(), "a.jpg", 0);
  WriteImage(path, Layer(4, kWidth + 1, kHeight));
  const std::string message =
      InputErrorMessage([&] { ReadMaskLayers(dir.path(), Image("a.jpg"), 1); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("9x6 but its image a.jpg is 8x6"), std::string::npos) << message;
}

TEST(MaskLayers, EightBitAndColourLayersAreRejected) {
  TempDir dir;
  const std::string path = MaskLayerPath(dir.path(), "a.jpg", 0);
  cv::Mat eight_bit;
  Layer(4).convertTo(eight_bit, CV_8U);
  WriteImage(path, eight_bit);
  std::string message = InputErrorMessage([&] { ReadMaskLayers(dir.path(), Image("a.jpg"), 1); });
  EXPECT_NE(message.find(path + ": mask layer is a 8-bit 1-channel image"), std::string::npos)
      << message;
  cv::Mat colour;
  cv::merge(std::vector<cv::Mat>{Layer(4), Layer(4), Layer(4)}, colour);
  WriteImage(path, colour);
  message = InputErrorMessage([&] { ReadMaskLayers(dir.path(), Image("a.jpg"), 1); });
  EXPECT_NE(message.find("16-bit 3-channel"), std::string::npos) << message;
}

TEST(MaskLayers, UnreadableFileNamesTheFile) {
  TempDir dir;
  const std::string path = MaskLayerPath(dir.path(), "a.jpg", 0);
  test::WriteRaw(path, "not a png");
  const std::string message =
      InputErrorMessage([&] { LoadMaskLayers(dir.path(), {Image("a.jpg")}, 3, nullptr); });
  EXPECT_NE(message.find(path + ": cannot read mask layer"), std::string::npos) << message;
}

TEST(MaskLayers, GapsAndInconsistentLevelCountsAreErrors) {
  TempDir dir;
  WriteImage(MaskLayerPath(dir.path(), "gap.jpg", 0), Layer(4));
  WriteImage(MaskLayerPath(dir.path(), "gap.jpg", 2), Layer(4));
  std::string message = InputErrorMessage([&] { CountMaskLevels(dir.path(), "gap.jpg"); });
  EXPECT_NE(message.find(MaskLayerPath(dir.path(), "gap.jpg", 1) + ": mask level 1 is missing"),
            std::string::npos)
      << message;

  WriteLayers(dir.path(), "a.jpg", 3);
  WriteLayers(dir.path(), "b.jpg", 2);
  message = InputErrorMessage([&] {
    LoadMaskLayers(dir.path(), {Image("a.jpg"), Image("b.jpg")}, 3, nullptr);
  });
  EXPECT_NE(message.find(MaskLayerPath(dir.path(), "b.jpg", 2) + ": missing"), std::string::npos)
      << message;
  EXPECT_NE(message.find("b.jpg has 2 mask levels but a.jpg has 3"), std::string::npos) << message;
}

}  // namespace
}  // namespace msp

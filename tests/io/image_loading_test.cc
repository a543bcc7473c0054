#include "io/image_loading.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;
using test::TempDir;

constexpr int kWidth = 16;
constexpr int kHeight = 12;

// A kWidth x kHeight colour gradient encoded as `extension` (".png", ...):
// blue grows along the rows, green down the columns, red is constant.
std::string Encoded(const std::string& extension) {
  cv::Mat image(kHeight, kWidth, CV_8UC3);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      image.at<cv::Vec3b>(row, col) = cv::Vec3b(col * 16, row * 20, 128);
    }
  }
  std::vector<uchar> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes));
  return std::string(bytes.begin(), bytes.end());
}

// The offset of the first start-of-frame (baseline, FF C0) segment's length.
size_t FrameHeaderOffset(const std::string& jpeg) {
  const size_t marker = jpeg.find("\xFF\xC0");
  EXPECT_NE(marker, std::string::npos);
  return marker + 2;
}

// `jpeg` with the frame header declaring width x height.
std::string WithDeclaredSize(std::string jpeg, int width, int height) {
  const size_t at = FrameHeaderOffset(jpeg);
  jpeg[at + 3] = static_cast<char>(height >> 8);
  jpeg[at + 4] = static_cast<char>(height & 0xFF);
  jpeg[at + 5] = static_cast<char>(width >> 8);
  jpeg[at + 6] = static_cast<char>(width & 0xFF);
  return jpeg;
}

std::string Load(const std::string& path, int width = kWidth, int height = kHeight) {
  DenseMap gray, color;
  return InputErrorMessage(
      [&] { LoadViewImage(path, width, height, width / 2, height / 2, &gray, &color); });
}

TEST(ImageLoading, EachFormatOfTheCameraSizeLoadsAtTheWorkingSize) {
  TempDir dir;
  for (const std::string extension : {".png", ".jpg", ".tiff", ".bmp"}) {
    const std::string path = dir.path() + "/a" + extension;
    test::WriteRaw(path, Encoded(extension));
    DenseMap gray, color;
    LoadViewImage(path, kWidth, kHeight, kWidth / 2, kHeight / 2, &gray, &color);
    EXPECT_EQ(gray.width, kWidth / 2) << extension;
    EXPECT_EQ(gray.height, kHeight / 2) << extension;
    EXPECT_EQ(gray.channels, 1) << extension;
    EXPECT_EQ(color.channels, 3) << extension;
    // In RGB order: red is constant, blue grows along the row.
    EXPECT_NEAR(color.At(2, 2, 0), 128.0f / 255.0f, 0.05f) << extension;
    EXPECT_LT(color.At(0, 0, 2), color.At(0, kWidth / 2 - 1, 2)) << extension;
  }
}

TEST(ImageLoading, JpegDeclaringAHugeImageIsRefusedFromItsHeader) {
  TempDir dir;
  const std::string path = dir.path() + "/a.jpg";
  test::WriteRaw(path, WithDeclaredSize(Encoded(".jpg"), 40000, 20000));
  const std::string message = Load(path);
  EXPECT_NE(message.find(path + ": image is 40000x20000 but its camera in the sparse model is "
                                "16x12"),
            std::string::npos)
      << message;
}

TEST(ImageLoading, JpegEndingBeforeItsFrameHeaderIsRefused) {
  TempDir dir;
  const std::string path = dir.path() + "/a.jpg";
  const std::string jpeg = Encoded(".jpg");
  test::WriteRaw(path, jpeg.substr(0, FrameHeaderOffset(jpeg)));
  const std::string message = Load(path);
  EXPECT_NE(message.find(path + ": cannot read image: corrupt JPEG header"), std::string::npos)
      << message;
}

TEST(ImageLoading, ImageOfTheWrongSizeIsRefused) {
  TempDir dir;
  const std::string path = dir.path() + "/a.png";
  test::WriteRaw(path, Encoded(".png"));
  const std::string message = Load(path, kWidth * 2, kHeight);
  EXPECT_NE(message.find(path + ": image is 16x12 but its camera in the sparse model is 32x12"),
            std::string::npos)
      << message;
}

// A camera beyond kMaxImagePixels is refused before its file is opened.
TEST(ImageLoading, CameraOverThePixelLimitIsRefusedBeforeReading) {
  const std::string path = "/nonexistent/a.png";
  const std::string message = Load(path, 40000, 20000);
  EXPECT_NE(message.find(path + ": its camera in the sparse model is 40000x20000, more than the " +
                         std::to_string(kMaxImagePixels) + " pixels"),
            std::string::npos)
      << message;
}

TEST(ImageLoading, UnreadableImageNamesTheFile) {
  TempDir dir;
  const std::string path = dir.path() + "/a.png";
  test::WriteRaw(path, "not an image");
  EXPECT_NE(Load(path).find(path + ": cannot read image"), std::string::npos);
}

// Formats no header check knows are never decoded (some of OpenCV's decoders
// abort on a malformed file).
TEST(ImageLoading, UnknownFormatIsRefusedBeforeDecoding) {
  TempDir dir;
  const std::string path = dir.path() + "/a.ppm";
  test::WriteRaw(path, Encoded(".ppm"));
  const std::string message = Load(path);
  EXPECT_NE(message.find(path + ": cannot read image: not a PNG, JPEG, TIFF or BMP file"),
            std::string::npos)
      << message;
  EXPECT_NE(Load(dir.path() + "/missing.png").find("no such file"), std::string::npos);
}

// At its own size the colour comes straight from the bytes; it must be the
// floats of converting the whole image and splitting it (as a resized one
// is), at a width whose last pixels a vectorised conversion does one by one.
TEST(ImageLoading, ColourAtItsOwnSizeIsThatOfTheFloatImage) {
  DecodedImage image;
  image.width = 37;
  image.height = 5;
  image.bgr.resize(37 * 5 * 3);
  for (size_t i = 0; i < image.bgr.size(); ++i) image.bgr[i] = static_cast<uint8_t>(i * 97 % 256);
  DenseMap color;
  ConvertViewImage(image, 37, 5, nullptr, &color);
  cv::Mat bgr_float;
  cv::Mat(5, 37, CV_8UC3, image.bgr.data()).convertTo(bgr_float, CV_32FC3, 1.0 / 255.0);
  for (int row = 0; row < 5; ++row) {
    for (int col = 0; col < 37; ++col) {
      const cv::Vec3f expected = bgr_float.at<cv::Vec3f>(row, col);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(color.At(row, col, c), expected[2 - c]);
    }
  }
  // With the grey plane asked for too, the colour is the same.
  DenseMap gray, color_too;
  ConvertViewImage(image, 37, 5, &gray, &color_too);
  EXPECT_EQ(color_too.data, color.data);
  EXPECT_EQ(gray.width, 37);
}

}  // namespace
}  // namespace msp

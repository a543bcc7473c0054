#include "io/image_header.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::TempDir;

// A 21x13 grey image encoded as `extension` (odd sides, so width and height
// cannot be swapped unnoticed).
std::string Encoded(const std::string& extension) {
  const cv::Mat image(13, 21, CV_8UC1, cv::Scalar(90));
  std::vector<uchar> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes));
  return std::string(bytes.begin(), bytes.end());
}

class ImageHeader : public ::testing::Test {
 protected:
  // Writes `bytes` and reads its format and declared size.
  bool Read(const std::string& bytes, ImageFormat* format) {
    test::WriteRaw(path_, bytes);
    *format = DetectImageFormat(path_);
    return ReadImageSize(path_, *format, &width_, &height_);
  }

  TempDir dir_;
  const std::string path_ = dir_.path() + "/image";
  uint32_t width_ = 0, height_ = 0;
};

TEST_F(ImageHeader, EveryFormatOpenCvWritesGivesItsSize) {
  const std::vector<std::pair<std::string, ImageFormat>> formats = {{".png", ImageFormat::kPng},
                                                                    {".jpg", ImageFormat::kJpeg},
                                                                    {".tiff", ImageFormat::kTiff},
                                                                    {".bmp", ImageFormat::kBmp}};
  for (const auto& [extension, expected] : formats) {
    ImageFormat format = ImageFormat::kUnknown;
    ASSERT_TRUE(Read(Encoded(extension), &format)) << extension;
    EXPECT_EQ(format, expected) << extension;
    EXPECT_EQ(width_, 21u) << extension;
    EXPECT_EQ(height_, 13u) << extension;
  }
}

TEST_F(ImageHeader, OtherFormatsAndEmptyFilesAreUnknown) {
  ImageFormat format = ImageFormat::kPng;
  EXPECT_FALSE(Read(Encoded(".pgm"), &format));
  EXPECT_EQ(format, ImageFormat::kUnknown);
  EXPECT_FALSE(Read("", &format));
  EXPECT_EQ(format, ImageFormat::kUnknown);
  EXPECT_EQ(DetectImageFormat(dir_.path() + "/missing.png"), ImageFormat::kUnknown);
}

TEST_F(ImageHeader, JpegSkipsSegmentsFillBytesAndStandAloneMarkers) {
  // SOI, an APP1 segment, fill bytes, RST0, then a progressive frame header
  // (SOF2) declaring 300x200.
  const std::string jpeg(
      "\xFF\xD8"
      "\xFF\xE1\x00\x05\x01\x02\x03"
      "\xFF\xFF\xFF\xD0"
      "\xFF\xC2\x00\x0B\x08\x00\xC8\x01\x2C\x03\x01\x22\x00",
      26);
  ImageFormat format;
  ASSERT_TRUE(Read(jpeg, &format));
  EXPECT_EQ(format, ImageFormat::kJpeg);
  EXPECT_EQ(width_, 300u);
  EXPECT_EQ(height_, 200u);
}

TEST_F(ImageHeader, MalformedJpegHeadersAreRefused) {
  ImageFormat format;
  // A table segment (DHT, FF C4) shares the SOF range but is no frame header.
  EXPECT_FALSE(
      Read(std::string("\xFF\xD8\xFF\xC4\x00\x07\x00\xC8\x01\x2C\x03\xFF\xD9", 13), &format));
  // A segment length running past the end of the file.
  EXPECT_FALSE(Read(std::string("\xFF\xD8\xFF\xE0\x7F\xFF\x00", 7), &format));
  // The scan starts before any frame header.
  EXPECT_FALSE(Read(std::string("\xFF\xD8\xFF\xDA\x00\x02", 6), &format));
  // A frame header cut short.
  EXPECT_FALSE(Read(std::string("\xFF\xD8\xFF\xC0\x00\x0B\x08\x00", 8), &format));
}

TEST_F(ImageHeader, TiffOfEitherByteOrderAndBigTiff) {
  ImageFormat format;
  // Big-endian classic TIFF: directory at 8 with 2 entries, ImageWidth as
  // SHORT 300 and ImageLength as LONG 70000.
  const std::string big_endian(
      "MM\x00\x2A\x00\x00\x00\x08"
      "\x00\x02"
      "\x01\x00\x00\x03\x00\x00\x00\x01\x01\x2C\x00\x00"
      "\x01\x01\x00\x04\x00\x00\x00\x01\x00\x01\x11\x70",
      34);
  ASSERT_TRUE(Read(big_endian, &format));
  EXPECT_EQ(format, ImageFormat::kTiff);
  EXPECT_EQ(width_, 300u);
  EXPECT_EQ(height_, 70000u);
  // Little-endian BigTIFF: offset size 8, directory at 16 with 2 entries of
  // 20 bytes, both LONG8.
  std::string big_tiff("II\x2B\x00\x08\x00\x00\x00\x10\x00\x00\x00\x00\x00\x00\x00", 16);
  big_tiff += std::string("\x02\x00\x00\x00\x00\x00\x00\x00", 8);
  big_tiff += std::string("\x00\x01\x10\x00\x01\x00\x00\x00\x00\x00\x00\x00", 12) +
              std::string("\x40\x9C\x00\x00\x00\x00\x00\x00", 8);
  big_tiff += std::string("\x01\x01\x10\x00\x01\x00\x00\x00\x00\x00\x00\x00", 12) +
              std::string("\x20\x4E\x00\x00\x00\x00\x00\x00", 8);
  ASSERT_TRUE(Read(big_tiff, &format));
  EXPECT_EQ(format, ImageFormat::kTiff);
  EXPECT_EQ(width_, 40000u);
  EXPECT_EQ(height_, 20000u);
  // A directory past the end of the file, and one without ImageLength.
  EXPECT_FALSE(Read(std::string("II\x2A\x00\xFF\x00\x00\x00", 8), &format));
  EXPECT_FALSE(Read(big_endian.substr(0, 22), &format));
}

TEST_F(ImageHeader, BmpOfEitherRowOrderAndTheCoreHeader) {
  ImageFormat format;
  std::string bmp = Encoded(".bmp");
  // A negative height: rows stored top-down.
  bmp[22] = static_cast<char>(-13);
  bmp[23] = bmp[24] = bmp[25] = static_cast<char>(0xFF);
  ASSERT_TRUE(Read(bmp, &format));
  EXPECT_EQ(width_, 21u);
  EXPECT_EQ(height_, 13u);
  // The OS/2 core header: 16-bit sides.
  const std::string core("BM\0\0\0\0\0\0\0\0\0\0\0\0\x0C\0\0\0\x15\0\x0D\0\x01\0\x18\0", 26);
  ASSERT_TRUE(Read(core, &format));
  EXPECT_EQ(width_, 21u);
  EXPECT_EQ(height_, 13u);
  EXPECT_FALSE(Read("BM", &format));
}

}  // namespace
}  // namespace msp

#include "io/dense_map_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

#include "tests/support/error_message.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

using test::InputErrorMessage;
using test::TempDir;

// value(row, col, c) of the hand-made normal map: distinct for every entry.
float NormalValue(int row, int col, int c) { return 0.5f * c + 0.125f * row - 0.0625f * col; }

// The bytes COLMAP's Mat<float>::Write produces for a 2 wide, 3 high,
// 3 channel map, built by hand: the ASCII header, then every x component
// (row-major), then every y, then every z, as little-endian float32.
std::string HandMadeNormalMapBytes() {
  std::string bytes = "2&3&3&";
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 2; ++col) {
        const float value = NormalValue(row, col, c);
        uint32_t bits;
        std::memcpy(&bits, &value, 4);
        for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<char>((bits >> (8 * b)) & 0xff));
      }
    }
  }
  return bytes;
}

TEST(DenseMapIo, RoundTripCreatesSubFolders) {
  TempDir dir;
  DenseMap depth(5, 4, 1);
  for (size_t i = 0; i < depth.data.size(); ++i) depth.data[i] = 0.1f * i;
  const std::string path = dir / "stereo/depth_maps/sub/a.jpg.geometric.bin";
  WriteDenseMap(path, depth);
  const DenseMap read = ReadDenseMap(path);
  EXPECT_EQ(read.width, 5);
  EXPECT_EQ(read.height, 4);
  EXPECT_EQ(read.channels, 1);
  EXPECT_EQ(read.data, depth.data);
  // No temporary file is left next to the output.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "stereo/depth_maps/sub")) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(DenseMapIo, ReadsColmapNormalMapLayout) {
  TempDir dir;
  test::WriteRaw(dir / "n.bin", HandMadeNormalMapBytes());
  const DenseMap map = ReadDenseMap(dir / "n.bin");
  ASSERT_EQ(map.width, 2);
  ASSERT_EQ(map.height, 3);
  ASSERT_EQ(map.channels, 3);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 2; ++col) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(map.At(row, col, c), NormalValue(row, col, c)) << row << " " << col << " " << c;
      }
    }
  }
}

TEST(DenseMapIo, WritesColmapBytesExactly) {
  TempDir dir;
  DenseMap map(2, 3, 3);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 2; ++col) {
      for (int c = 0; c < 3; ++c) map.At(row, col, c) = NormalValue(row, col, c);
    }
  }
  WriteDenseMap(dir / "n.bin", map);
  EXPECT_EQ(test::ReadRaw(dir / "n.bin"), HandMadeNormalMapBytes());
}

TEST(DenseMapIo, HeaderWhitespaceIsAccepted) {
  // COLMAP reads the header with operator>>, which skips whitespace.
  TempDir dir;
  std::string bytes = HandMadeNormalMapBytes();
  bytes.replace(0, 6, " 2& 3&\n3&");
  test::WriteRaw(dir / "n.bin", bytes);
  EXPECT_EQ(ReadDenseMap(dir / "n.bin").At(2, 1, 2), NormalValue(2, 1, 2));
}

TEST(DenseMapIo, TruncatedFile) {
  TempDir dir;
  const std::string bytes = HandMadeNormalMapBytes();
  test::WriteRaw(dir / "n.bin", bytes.substr(0, bytes.size() - 3));
  const std::string message = InputErrorMessage([&] { ReadDenseMap(dir / "n.bin"); });
  EXPECT_NE(message.find("n.bin: file size 75 bytes does not match its header 2&3&3& "
                         "(expected 78 bytes, file is truncated)"),
            std::string::npos)
      << message;
}

TEST(DenseMapIo, TrailingBytes) {
  TempDir dir;
  test::WriteRaw(dir / "n.bin", HandMadeNormalMapBytes() + "xy");
  EXPECT_NE(
      InputErrorMessage([&] { ReadDenseMap(dir / "n.bin"); }).find("does not match its header"),
      std::string::npos);
}

TEST(DenseMapIo, HeaderLargerThanFile) {
  TempDir dir;
  test::WriteRaw(dir / "d.bin", "4000&3000&1&" + std::string(64, '\0'));
  const std::string message = InputErrorMessage([&] { ReadDenseMap(dir / "d.bin"); });
  EXPECT_NE(message.find("file is truncated"), std::string::npos) << message;
  EXPECT_NE(message.find("expected 48000012 bytes"), std::string::npos) << message;
}

TEST(DenseMapIo, GarbageHeader) {
  TempDir dir;
  for (const std::string& bytes :
       {std::string("\x89PNG\r\n\x1a\n garbage"), std::string("12&"), std::string("1&2"),
        std::string("-2&3&1&abcdefghijklmnopqrstuvwx"), std::string(""),
        std::string("99999999999999999999&1&1&")}) {
    test::WriteRaw(dir / "g.bin", bytes);
    const std::string message = InputErrorMessage([&] { ReadDenseMap(dir / "g.bin"); });
    EXPECT_NE(message.find("g.bin: not a COLMAP depth/normal map"), std::string::npos) << message;
  }
}

TEST(DenseMapIo, InvalidHeaderValues) {
  TempDir dir;
  test::WriteRaw(dir / "z.bin", "0&3&1&");
  EXPECT_NE(
      InputErrorMessage([&] { ReadDenseMap(dir / "z.bin"); }).find("invalid map header 0&3&1&"),
      std::string::npos);
  test::WriteRaw(dir / "c.bin", "1&1&9&" + std::string(36, '\0'));
  EXPECT_NE(InputErrorMessage([&] { ReadDenseMap(dir / "c.bin"); }).find("channels 1..4"),
            std::string::npos);
}

TEST(DenseMapIo, MissingFile) {
  TempDir dir;
  EXPECT_NE(InputErrorMessage([&] {
              ReadDenseMap(dir / "none.bin");
            }).find("none.bin: file does not exist"),
            std::string::npos);
}

TEST(DenseMapIo, RefusesNonFiniteValues) {
  TempDir dir;
  DenseMap map(2, 2, 1, 1.0f);
  map.At(1, 0) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(WriteDenseMap(dir / "nan.bin", map), std::logic_error);
  map.At(1, 0) = std::numeric_limits<float>::infinity();
  EXPECT_THROW(WriteDenseMap(dir / "inf.bin", map), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "nan.bin"));
  EXPECT_FALSE(std::filesystem::exists(dir / "inf.bin"));
}

TEST(DenseMapIo, RefusesInconsistentMap) {
  TempDir dir;
  DenseMap map(2, 2, 1);
  map.data.pop_back();
  EXPECT_THROW(WriteDenseMap(dir / "bad.bin", map), std::logic_error);
}

}  // namespace
}  // namespace msp

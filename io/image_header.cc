#include "io/image_header.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "io/png_header.h"

namespace msp {
namespace {

// JPEG markers (ITU T.81, table B.1) are 0xFF then a code; any number of 0xFF
// fill bytes may precede the code.
constexpr int kJpegMarkerPrefix = 0xFF;
constexpr int kJpegStartOfImage = 0xD8;
constexpr int kJpegEndOfImage = 0xD9;
constexpr int kJpegStartOfScan = 0xDA;
// Markers that stand alone, without a length: TEM and RST0..RST7.
constexpr int kJpegTemporary = 0x01;
constexpr int kJpegFirstRestart = 0xD0;
constexpr int kJpegLastRestart = 0xD7;
// A frame header: the 2-byte segment length, precision (1 byte), height and
// width (2 bytes each, big-endian).
constexpr int kJpegFrameHeaderBytes = 7;
constexpr int kJpegHeightOffset = 3;
constexpr int kJpegWidthOffset = 5;

// TIFF (TIFF 6.0, section 2; BigTIFF): byte order "II" or "MM", the version
// (42, or 43 for BigTIFF), then the offset of the first image file directory.
constexpr int kTiffVersion = 42;
constexpr int kBigTiffVersion = 43;
constexpr int kTiffImageWidthTag = 256;
constexpr int kTiffImageLengthTag = 257;
constexpr int kTiffShort = 3;
constexpr int kTiffLong = 4;
constexpr int kTiffLong8 = 16;
// Directories list their entries in tag order and ImageWidth / ImageLength
// come first; a directory claiming more entries than this is malformed.
constexpr uint64_t kTiffMaxEntries = 4096;

// BMP: "BM", the file header (14 bytes), then the info header, whose size
// tells its kind: 12 bytes (OS/2 core header, 16-bit sides) or more (32-bit
// sides; a negative height means top-down rows).
constexpr int kBmpInfoOffset = 14;
constexpr uint32_t kBmpCoreHeaderSize = 12;

// Reads `size` bytes at `offset`; false when the file ends before.
bool ReadAt(std::ifstream* file, uint64_t offset, unsigned char* bytes, size_t size) {
  file->clear();
  file->seekg(static_cast<std::streamoff>(offset));
  return static_cast<bool>(file->read(reinterpret_cast<char*>(bytes), size));
}

// An unsigned integer of `size` bytes (at most 8) in the given byte order.
uint64_t Unsigned(const unsigned char* bytes, int size, bool big_endian) {
  uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    value = (value << 8) | bytes[big_endian ? i : size - 1 - i];
  }
  return value;
}

bool IsJpegStartOfFrame(int code) {
  // SOF0..SOF15 but DHT (C4), JPG (C8) and DAC (CC), which share the range.
  return code >= 0xC0 && code <= 0xCF && code != 0xC4 && code != 0xC8 && code != 0xCC;
}

bool ReadJpegSize(std::ifstream* file, uint32_t* width, uint32_t* height) {
  // Segment by segment, skipping each by its length: only the markers before
  // the frame header are read, never the scan data.
  file->seekg(2);  // after the start-of-image marker
  int byte = file->get();
  while (byte == kJpegMarkerPrefix) {
    int code = file->get();
    while (code == kJpegMarkerPrefix) code = file->get();  // fill bytes
    if (code == std::char_traits<char>::eof()) return false;
    if (code == kJpegTemporary || (code >= kJpegFirstRestart && code <= kJpegLastRestart)) {
      byte = file->get();
      continue;
    }
    if (code == kJpegEndOfImage || code == kJpegStartOfScan || code == kJpegStartOfImage) {
      return false;
    }
    unsigned char segment[kJpegFrameHeaderBytes] = {};
    if (!file->read(reinterpret_cast<char*>(segment), 2)) return false;
    const uint64_t length = Unsigned(segment, 2, /*big_endian=*/true);
    if (length < 2) return false;
    if (IsJpegStartOfFrame(code)) {
      if (length < kJpegFrameHeaderBytes ||
          !file->read(reinterpret_cast<char*>(segment + 2), kJpegFrameHeaderBytes - 2)) {
        return false;
      }
      *height = static_cast<uint32_t>(Unsigned(segment + kJpegHeightOffset, 2, true));
      *width = static_cast<uint32_t>(Unsigned(segment + kJpegWidthOffset, 2, true));
      return true;
    }
    if (!file->seekg(static_cast<std::streamoff>(length - 2), std::ios::cur)) return false;
    byte = file->get();
  }
  return false;
}

bool ReadTiffSize(std::ifstream* file, uint32_t* width, uint32_t* height) {
  unsigned char header[16] = {};
  if (!ReadAt(file, 0, header, 8)) return false;
  const bool big_endian = header[0] == 'M';
  const uint64_t version = Unsigned(header + 2, 2, big_endian);
  const bool big_tiff = version == kBigTiffVersion;
  if (version != kTiffVersion && !big_tiff) return false;
  // Classic: 4-byte offsets, 2-byte entry counts, 12-byte entries with a
  // 4-byte value; BigTIFF: 8, 8, 20 and 8.
  const int offset_size = big_tiff ? 8 : 4;
  const int count_size = big_tiff ? 8 : 2;
  const int entry_size = big_tiff ? 20 : 12;
  if (big_tiff && !ReadAt(file, 0, header, 16)) return false;
  const uint64_t directory = Unsigned(header + (big_tiff ? 8 : 4), offset_size, big_endian);
  unsigned char bytes[20] = {};
  if (!ReadAt(file, directory, bytes, count_size)) return false;
  const uint64_t entries = Unsigned(bytes, count_size, big_endian);
  if (entries > kTiffMaxEntries) return false;
  bool have_width = false, have_height = false;
  for (uint64_t i = 0; i < entries && !(have_width && have_height); ++i) {
    if (!ReadAt(file, directory + count_size + i * entry_size, bytes, entry_size)) return false;
    const uint64_t tag = Unsigned(bytes, 2, big_endian);
    if (tag != kTiffImageWidthTag && tag != kTiffImageLengthTag) continue;
    const uint64_t type = Unsigned(bytes + 2, 2, big_endian);
    const unsigned char* value = bytes + 4 + (big_tiff ? 8 : 4);
    uint64_t side = 0;
    if (type == kTiffShort) {
      side = Unsigned(value, 2, big_endian);
    } else if (type == kTiffLong) {
      side = Unsigned(value, 4, big_endian);
    } else if (type == kTiffLong8 && big_tiff) {
      side = Unsigned(value, 8, big_endian);
    } else {
      return false;
    }
    if (side > UINT32_MAX) return false;
    (tag == kTiffImageWidthTag ? *width : *height) = static_cast<uint32_t>(side);
    (tag == kTiffImageWidthTag ? have_width : have_height) = true;
  }
  return have_width && have_height;
}

bool ReadBmpSize(std::ifstream* file, uint32_t* width, uint32_t* height) {
  unsigned char info[12] = {};
  if (!ReadAt(file, kBmpInfoOffset, info, sizeof(info))) return false;
  const uint32_t info_size = static_cast<uint32_t>(Unsigned(info, 4, false));
  if (info_size < kBmpCoreHeaderSize) return false;
  if (info_size == kBmpCoreHeaderSize) {
    *width = static_cast<uint32_t>(Unsigned(info + 4, 2, false));
    *height = static_cast<uint32_t>(Unsigned(info + 6, 2, false));
    return true;
  }
  const int64_t w = static_cast<int32_t>(Unsigned(info + 4, 4, false));
  const int64_t h = static_cast<int32_t>(Unsigned(info + 8, 4, false));
  if (w < 0) return false;
  *width = static_cast<uint32_t>(w);
  *height = static_cast<uint32_t>(h < 0 ? -h : h);
  return true;
}

}  // namespace

const char* ImageFormatName(ImageFormat format) {
  switch (format) {
    case ImageFormat::kPng:
      return "PNG";
    case ImageFormat::kJpeg:
      return "JPEG";
    case ImageFormat::kTiff:
      return "TIFF";
    case ImageFormat::kBmp:
      return "BMP";
    case ImageFormat::kUnknown:
      break;
  }
  return "unknown";
}

ImageFormat DetectImageFormat(const std::string& path) {
  if (HasPngSignature(path)) return ImageFormat::kPng;
  unsigned char head[4] = {};
  std::ifstream file(path, std::ios::binary);
  if (!file.read(reinterpret_cast<char*>(head), sizeof(head))) return ImageFormat::kUnknown;
  if (head[0] == kJpegMarkerPrefix && head[1] == kJpegStartOfImage &&
      head[2] == kJpegMarkerPrefix) {
    return ImageFormat::kJpeg;
  }
  if ((std::memcmp(head, "II", 2) == 0 && (head[2] == kTiffVersion || head[2] == kBigTiffVersion) &&
       head[3] == 0) ||
      (std::memcmp(head, "MM", 2) == 0 && head[2] == 0 &&
       (head[3] == kTiffVersion || head[3] == kBigTiffVersion))) {
    return ImageFormat::kTiff;
  }
  if (std::memcmp(head, "BM", 2) == 0) return ImageFormat::kBmp;
  return ImageFormat::kUnknown;
}

bool ReadImageSize(const std::string& path, ImageFormat format, uint32_t* width, uint32_t* height) {
  if (format == ImageFormat::kPng) return ReadPngSize(path, width, height);
  std::ifstream file(path, std::ios::binary);
  if (!file) return false;
  switch (format) {
    case ImageFormat::kJpeg:
      return ReadJpegSize(&file, width, height);
    case ImageFormat::kTiff:
      return ReadTiffSize(&file, width, height);
    case ImageFormat::kBmp:
      return ReadBmpSize(&file, width, height);
    default:
      return false;
  }
}

}  // namespace msp

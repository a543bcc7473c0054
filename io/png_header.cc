#include "io/png_header.h"

#include <algorithm>
#include <fstream>

namespace msp {
namespace {

// The PNG signature, then the first chunk's length (4 bytes) and type.
constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr int kChunkTypeOffset = 12;
constexpr char kHeaderChunk[] = "IHDR";
// IHDR's data starts with the width and the height, 4 bytes each, big-endian.
constexpr int kWidthOffset = 16;
constexpr int kHeightOffset = 20;
constexpr int kHeaderBytes = 24;

uint32_t BigEndian32(const unsigned char* bytes) {
  return (uint32_t{bytes[0]} << 24) | (uint32_t{bytes[1]} << 16) | (uint32_t{bytes[2]} << 8) |
         uint32_t{bytes[3]};
}

}  // namespace

bool HasPngSignature(const std::string& path) {
  unsigned char signature[sizeof(kSignature)] = {};
  std::ifstream file(path, std::ios::binary);
  file.read(reinterpret_cast<char*>(signature), sizeof(signature));
  return file && std::equal(kSignature, kSignature + sizeof(kSignature), signature);
}

bool ReadPngSize(const std::string& path, uint32_t* width, uint32_t* height) {
  unsigned char header[kHeaderBytes] = {};
  std::ifstream file(path, std::ios::binary);
  file.read(reinterpret_cast<char*>(header), sizeof(header));
  if (!file || !std::equal(kSignature, kSignature + sizeof(kSignature), header) ||
      !std::equal(header + kChunkTypeOffset, header + kChunkTypeOffset + 4, kHeaderChunk)) {
    return false;
  }
  *width = BigEndian32(header + kWidthOffset);
  *height = BigEndian32(header + kHeightOffset);
  return true;
}

}  // namespace msp

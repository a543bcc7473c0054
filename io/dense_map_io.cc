#include "io/dense_map_io.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "io/binary_io.h"
#include "io/errors.h"
#include "io/file_util.h"

namespace msp {
namespace {

// Sanity bounds for a header: no camera makes maps wider than this, and
// COLMAP writes 1 (depth, consistency) or 3 (normal) channels; 4 leaves room
// for RGBA-like maps. Anything beyond is a corrupt or foreign file.
constexpr long long kMaxMapSide = 1 << 17;
constexpr long long kMaxChannels = 4;
// "131072&131072&4&" is 16 characters; leading whitespace makes it longer.
constexpr size_t kMaxHeaderChars = 64;

// Parses one "<integer>&" field starting at *pos. COLMAP reads the header with
// `stream >> value >> separator`, so whitespace before a number is accepted.
bool ParseField(const std::string& bytes, size_t* pos, long long* value) {
  size_t p = *pos;
  while (p < bytes.size() && p < kMaxHeaderChars &&
         std::isspace(static_cast<unsigned char>(bytes[p]))) {
    ++p;
  }
  const size_t digits_begin = p;
  long long v = 0;
  while (p < bytes.size() && p < kMaxHeaderChars && bytes[p] >= '0' && bytes[p] <= '9') {
    v = v * 10 + (bytes[p] - '0');
    if (v > kMaxMapSide) return false;
    ++p;
  }
  if (p == digits_begin || p >= bytes.size() || bytes[p] != '&') return false;
  *value = v;
  *pos = p + 1;
  return true;
}

}  // namespace

DenseMap ReadDenseMap(const std::string& path) {
  const std::string bytes = ReadFileToString(path);
  size_t pos = 0;
  long long width = 0, height = 0, channels = 0;
  if (!ParseField(bytes, &pos, &width) || !ParseField(bytes, &pos, &height) ||
      !ParseField(bytes, &pos, &channels)) {
    throw InputError(path + ": not a COLMAP depth/normal map (expected a \"<width>&<height>&" +
                     "<channels>&\" header with sides <= " + std::to_string(kMaxMapSide) + ")");
  }
  if (width <= 0 || height <= 0 || channels <= 0 || channels > kMaxChannels) {
    throw InputError(path + ": invalid map header " + std::to_string(width) + "&" +
                     std::to_string(height) + "&" + std::to_string(channels) +
                     "& (sides must be positive, channels 1.." + std::to_string(kMaxChannels) +
                     ")");
  }
  const size_t num_values = static_cast<size_t>(width) * height * channels;
  const size_t expected_size = pos + num_values * sizeof(float);
  if (bytes.size() != expected_size) {
    throw InputError(path + ": file size " + std::to_string(bytes.size()) +
                     " bytes does not match its header " + std::to_string(width) + "&" +
                     std::to_string(height) + "&" + std::to_string(channels) + "& (expected " +
                     std::to_string(expected_size) + " bytes" +
                     (bytes.size() < expected_size ? ", file is truncated)" : ")"));
  }
  DenseMap map(static_cast<int>(width), static_cast<int>(height), static_cast<int>(channels));
  std::memcpy(map.data.data(), bytes.data() + pos, num_values * sizeof(float));
  if (kHostIsBigEndian) {
    for (float& value : map.data) value = LittleEndianToHost(value);
  }
  return map;
}

void WriteDenseMap(const std::string& path, const DenseMap& map) {
  if (map.width <= 0 || map.height <= 0 || map.channels <= 0 ||
      map.data.size() != static_cast<size_t>(map.width) * map.height * map.channels) {
    throw std::logic_error("WriteDenseMap(" + path + "): map size does not match its data");
  }
  // COLMAP's fusion treats NaN as a valid depth (it passes `depth <= 0`), so a
  // single NaN becomes garbage points: outputs must never contain one.
  for (size_t i = 0; i < map.data.size(); ++i) {
    if (!std::isfinite(map.data[i])) {
      throw std::logic_error("WriteDenseMap(" + path + "): non-finite value at index " +
                             std::to_string(i));
    }
  }
  const std::string header = std::to_string(map.width) + "&" + std::to_string(map.height) + "&" +
                             std::to_string(map.channels) + "&";
  std::string bytes = header;
  bytes.resize(header.size() + map.data.size() * sizeof(float));
  char* out = &bytes[header.size()];
  if (kHostIsBigEndian) {
    for (size_t i = 0; i < map.data.size(); ++i) {
      const float value = LittleEndianToHost(map.data[i]);
      std::memcpy(out + i * sizeof(float), &value, sizeof(float));
    }
  } else {
    std::memcpy(out, map.data.data(), map.data.size() * sizeof(float));
  }
  WriteFileAtomic(path, bytes);
}

}  // namespace msp

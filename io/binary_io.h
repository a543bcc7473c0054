// Little-endian readers / writers over in-memory buffers for COLMAP's binary
// files. The reader checks every access against the buffer end, so a
// truncated file becomes an InputError naming the file instead of garbage.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "io/errors.h"

namespace msp {

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
constexpr bool kHostIsBigEndian = true;
#else
constexpr bool kHostIsBigEndian = false;
#endif

// Reverses the bytes of `value` on big-endian hosts (COLMAP files are LE).
template <typename T>
T LittleEndianToHost(T value) {
  static_assert(std::is_trivially_copyable<T>::value, "plain values only");
  if (kHostIsBigEndian) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i) {
      const unsigned char tmp = bytes[i];
      bytes[i] = bytes[sizeof(T) - 1 - i];
      bytes[sizeof(T) - 1 - i] = tmp;
    }
    std::memcpy(&value, bytes, sizeof(T));
  }
  return value;
}

class ByteReader {
 public:
  ByteReader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  template <typename T>
  T Read() {
    Require(sizeof(T), "value");
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return LittleEndianToHost(value);
  }

  // Bytes up to (not including) the next '\0', which is consumed.
  std::string ReadNullTerminated() {
    const size_t end = bytes_.find('\0', pos_);
    if (end == std::string::npos) {
      Fail("unterminated string at byte " + std::to_string(pos_));
    }
    std::string value = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return value;
  }

  // Reads a record count and checks that `count` records of at least
  // `min_record_bytes` each fit in the rest of the file, so that an absurd
  // count in a corrupt file fails here instead of allocating gigabytes.
  uint64_t ReadCount(size_t min_record_bytes, const char* what) {
    const uint64_t count = Read<uint64_t>();
    if (min_record_bytes > 0 && count > Remaining() / min_record_bytes) {
      Fail(std::string("count of ") + what + " (" + std::to_string(count) +
           ") does not fit in the remaining " + std::to_string(Remaining()) + " bytes");
    }
    return count;
  }

  size_t Remaining() const { return bytes_.size() - pos_; }
  size_t Position() const { return pos_; }

  [[noreturn]] void Fail(const std::string& what) const {
    throw InputError(path_ + ": corrupt or truncated file: " + what);
  }

 private:
  void Require(size_t n, const char* what) const {
    if (Remaining() < n) {
      Fail(std::string("unexpected end of file reading a ") + what + " at byte " +
           std::to_string(pos_));
    }
  }

  const std::string& bytes_;
  const std::string path_;
  size_t pos_ = 0;
};

class ByteWriter {
 public:
  template <typename T>
  void Write(T value) {
    value = LittleEndianToHost(value);  // the swap is its own inverse
    const char* p = reinterpret_cast<const char*>(&value);
    bytes_.append(p, sizeof(T));
  }
  void WriteNullTerminated(const std::string& s) {
    bytes_.append(s);
    bytes_.push_back('\0');
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

}  // namespace msp

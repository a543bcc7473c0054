// Helpers for the colmap_ext tests: the shared self-removing temporary folder
// (temp_dir.h), raw file access and capturing the message of an expected
// InputError.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "colmap_ext/errors.h"
#include "tests/temp_dir.h"

namespace msp {
namespace test {

inline void WriteRaw(const std::string& path, const std::string& bytes) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string ReadRaw(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// Runs `fn`; returns the InputError message, or "<no error>" if none was thrown.
template <typename Fn>
std::string InputErrorMessage(Fn&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace test
}  // namespace msp

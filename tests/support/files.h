// Raw file access for tests that write inputs by hand or compare outputs
// byte for byte.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace msp {
namespace test {

// Creates the folders `path` is to be written in.
inline void CreateParentFolders(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
}

// Writes `bytes` to `path`, creating its parent folders.
inline void WriteRaw(const std::string& path, const std::string& bytes) {
  CreateParentFolders(path);
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The bytes of `path` ("" when it cannot be read).
inline std::string ReadRaw(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

}  // namespace test
}  // namespace msp

#include "fuzz/fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace msp {
namespace fuzz {
namespace {

void RemoveInputDir() {
  std::error_code ignored;
  std::filesystem::remove_all(InputDir(), ignored);
}

}  // namespace

const std::string& InputDir() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/msp-fuzz-XXXXXX";
    if (::mkdtemp(&pattern[0]) == nullptr) {
      std::perror("mkdtemp");
      std::abort();
    }
    return pattern;
  }();
  static const bool registered = (std::atexit(RemoveInputDir), true);
  (void)registered;
  return dir;
}

std::string WriteInputFile(const std::string& name, const std::string& bytes) {
  const std::string path = InputDir() + "/" + name;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.close();
  // A fuzzer that silently tests empty files would find nothing.
  if (!file) throw std::runtime_error("cannot write fuzz input " + path);
  return path;
}

std::vector<std::string> SplitInput(const uint8_t* data, size_t size, size_t count) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = kPartSeparator;
  std::vector<std::string> parts;
  size_t begin = 0;
  while (parts.size() + 1 < count) {
    const size_t end = input.find(separator, begin);
    if (end == std::string::npos) break;
    parts.push_back(input.substr(begin, end - begin));
    begin = end + separator.size();
  }
  parts.push_back(input.substr(std::min(begin, input.size())));
  parts.resize(count);
  return parts;
}

}  // namespace fuzz
}  // namespace msp

// A self-removing temporary folder for tests that write files.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <string>

namespace msp {
namespace test {

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "msp_test_XXXXXX").string();
    path_ = ::mkdtemp(&pattern[0]);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

}  // namespace test
}  // namespace msp

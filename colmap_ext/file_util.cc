#include "colmap_ext/file_util.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "colmap_ext/errors.h"

namespace msp {
namespace fs = std::filesystem;

void CreateDirectories(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError("cannot create folder " + dir + ": " +
                     (ec ? ec.message() : std::string("not a directory")));
  }
}

void CreateParentDirectories(const std::string& path) {
  CreateDirectories(fs::path(path).parent_path().string());
}

std::string ReadFileToString(const std::string& path) {
  if (!IsFile(path)) {
    throw InputError(path + ": file does not exist");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw InputError(path + ": cannot open file: " + std::strerror(errno));
  }
  std::ostringstream buffer;
  buffer << file.rdbuf();
  if (file.bad()) {
    throw InputError(path + ": read error");
  }
  return buffer.str();
}

void WriteFileAtomic(const std::string& path, const std::string& bytes) {
  CreateParentDirectories(path);
  // The pid keeps concurrent writers (several processes on one workspace)
  // from clobbering each other's temporary file.
  const std::string tmp_path = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream file(tmp_path, std::ios::binary | std::ios::trunc);
    if (!file) {
      throw InputError("cannot write " + path + ": " + std::strerror(errno));
    }
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.flush();
    if (!file) {
      std::error_code ignored;
      fs::remove(tmp_path, ignored);
      throw InputError("cannot write " + path + " (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp_path, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp_path, ignored);
    throw InputError("cannot rename " + tmp_path + " to " + path + ": " + ec.message());
  }
}

bool IsFile(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool IsDirectory(const std::string& path) {
  std::error_code ec;
  return fs::is_directory(path, ec);
}

std::string JoinPaths(const std::string& a, const std::string& b) {
  if (a.empty()) return b;
  if (a.back() == '/') return a + b;
  return a + "/" + b;
}

}  // namespace msp

#include "io/file_util.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "io/errors.h"

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

namespace {

// Writes all of `bytes` to `fd` and flushes them to the disk; false with errno
// set on failure (ENOSPC on a full disk, EFBIG beyond `ulimit -f`, EIO).
bool WriteAllAndSync(int fd, const std::string& bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    written += static_cast<size_t>(n);
  }
  // Data on the disk before the rename makes the new name visible: after a
  // crash of the machine the name holds the whole file or is absent.
  return ::fdatasync(fd) == 0;
}

}  // namespace

void WriteFileAtomic(const std::string& path, const std::string& bytes) {
  CreateParentDirectories(path);
  // The pid keeps concurrent writers (several processes on one workspace)
  // from clobbering each other's temporary file; the name does not end like
  // any file a reader looks for, and msp_stereo removes those a killed run
  // left (stale_files.h).
  const std::string tmp_path = TemporaryPath(path, ::getpid());
  const int fd = ::open(tmp_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw InputError("cannot write " + path + ": " + std::strerror(errno));
  }
  const bool ok = WriteAllAndSync(fd, bytes);
  const int write_errno = errno;
  if (::close(fd) != 0 || !ok) {
    const int error = ok ? errno : write_errno;
    ::unlink(tmp_path.c_str());
    throw InputError("cannot write " + path + ": " + std::strerror(error));
  }
  if (::rename(tmp_path.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp_path.c_str());
    throw InputError("cannot rename " + tmp_path + " to " + path + ": " + std::strerror(error));
  }
}

std::string TemporaryPath(const std::string& path, long pid) {
  return path + kTemporarySuffix + std::to_string(pid);
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

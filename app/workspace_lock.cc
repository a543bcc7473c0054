#include "app/workspace_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "io/errors.h"
#include "io/file_util.h"

namespace msp {
namespace {

std::string HostName() {
  char host[256] = {};
  if (::gethostname(host, sizeof(host) - 1) != 0) return "unknown host";
  return host;
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// The holder line of the lock file, without its newline; "" when unreadable.
std::string ReadHolder(int fd) {
  char text[512] = {};
  const ssize_t n = ::pread(fd, text, sizeof(text) - 1, 0);
  if (n <= 0) return "";
  std::string holder(text, static_cast<size_t>(n));
  const size_t end = holder.find('\n');
  return end == std::string::npos ? holder : holder.substr(0, end);
}

}  // namespace

std::string WorkspaceLockPath(const std::string& stereo_dir) {
  return JoinPaths(stereo_dir, kWorkspaceLockName);
}

WorkspaceLock::WorkspaceLock(const std::string& stereo_dir, const std::string& file_name,
                             LockMode mode)
    : path_(JoinPaths(stereo_dir, file_name)) {
  CreateDirectories(stereo_dir);
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  // flock needs no write access: an existing lock file in a read-only stereo/
  // still locks, and the run stops at the first file it cannot write, naming it.
  const bool writable = fd_ >= 0;
  if (!writable) fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    throw InputError("cannot create the workspace lock " + path_ + ": " + std::strerror(errno));
  }
  if (::flock(fd_, (mode == LockMode::kShared ? LOCK_SH : LOCK_EX) | LOCK_NB) != 0) {
    const int error = errno;
    const std::string holder = ReadHolder(fd_);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw InputError("the workspace is in use by another msp_stereo (" +
                       (holder.empty() ? std::string("holder unknown") : holder) + "; lock file " +
                       path_ +
                       "): wait for it to finish, or stop it (Ctrl-C, or kill with its pid) and "
                       "run again to resume");
    }
    throw InputError("cannot lock " + path_ + ": " + std::strerror(error));
  }
  const std::string holder =
      "pid " + std::to_string(::getpid()) + " on " + HostName() + " since " + UtcNow() + "\n";
  // Best effort: the lock is the flock, the text only tells people who holds
  // it (a full disk shows up, with a file's name, at the first map written).
  const bool described =
      writable && ::ftruncate(fd_, 0) == 0 &&
      ::pwrite(fd_, holder.data(), holder.size(), 0) == static_cast<ssize_t>(holder.size());
  (void)described;
}

WorkspaceLock::~WorkspaceLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace msp

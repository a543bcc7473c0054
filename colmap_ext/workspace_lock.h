// One msp_stereo per workspace: a run holds an advisory lock (flock) on
// stereo/msp_stereo.lock, which records the holder's pid, host and start time.
// The kernel drops the lock when the holder exits or is killed (kill -9
// included), so a crashed run never blocks the next one; the file itself stays
// and only describes the last holder. On NFS flock needs the server's lock
// support (NFSv4, or v3 with lockd), as every Slurm cluster's home has.
#pragma once

#include <string>

namespace msp {

class WorkspaceLock {
 public:
  // Takes the lock of <stereo_dir>/msp_stereo.lock, creating the file. Throws
  // InputError when another process holds it (naming that process and how to
  // go on) or when the file cannot be created (naming it).
  explicit WorkspaceLock(const std::string& stereo_dir);
  ~WorkspaceLock();
  WorkspaceLock(const WorkspaceLock&) = delete;
  WorkspaceLock& operator=(const WorkspaceLock&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

// <stereo_dir>/msp_stereo.lock
std::string WorkspaceLockPath(const std::string& stereo_dir);

}  // namespace msp

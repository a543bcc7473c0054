// One msp_stereo per workspace: a run holds an advisory lock (flock) on
// stereo/msp_stereo.lock, which records the holder's pid, host and start time.
// The kernel drops the lock when the holder exits or is killed (kill -9
// included), so a crashed run never blocks the next one; the file itself stays
// and only describes the last holder. On NFS flock needs the server's lock
// support (NFSv4, or v3 with lockd), as every Slurm cluster's home has.
//
// The processes of a sharded run (--MspStereo.shard, image_list) share the
// workspace: each holds msp_stereo.lock shared, which keeps an unsharded run
// out while they work (and them out while one works), and its shard's own
// lock file exclusively, which refuses a second process for the same shard.
#pragma once

#include <string>

namespace msp {

constexpr char kWorkspaceLockName[] = "msp_stereo.lock";

enum class LockMode { kExclusive, kShared };

class WorkspaceLock {
 public:
  // Takes the lock of <stereo_dir>/<file_name>, creating the file. Throws
  // InputError when another process holds it (naming that process and how to
  // go on) or when the file cannot be created (naming it).
  explicit WorkspaceLock(const std::string& stereo_dir,
                         const std::string& file_name = kWorkspaceLockName,
                         LockMode mode = LockMode::kExclusive);
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

#include "app/workspace_lock.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <memory>
#include <string>

#include "io/errors.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

TEST(WorkspaceLockTest, ASecondHolderIsRefusedWithTheFirstNamed) {
  test::TempDir dir;
  const std::string stereo = dir / "stereo";
  auto first = std::make_unique<WorkspaceLock>(stereo);
  const std::string holder = test::ReadRaw(WorkspaceLockPath(stereo));
  EXPECT_EQ(holder.rfind("pid " + std::to_string(::getpid()) + " on ", 0), 0u) << holder;
  try {
    WorkspaceLock second(stereo);
    FAIL() << "the second lock was taken";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("in use by another msp_stereo (pid " + std::to_string(::getpid())),
              std::string::npos)
        << message;
    EXPECT_NE(message.find(WorkspaceLockPath(stereo)), std::string::npos) << message;
  }
  first.reset();
  EXPECT_NO_THROW(WorkspaceLock again(stereo));
}

TEST(WorkspaceLockTest, AKilledHolderDoesNotBlock) {
  test::TempDir dir;
  const std::string stereo = dir / "stereo";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    WorkspaceLock lock(stereo);
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(2);
    ::pause();
    ::_exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  EXPECT_THROW(WorkspaceLock busy(stereo), InputError);
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_NO_THROW(WorkspaceLock taken(stereo));
  ::close(ready[0]);
  ::close(ready[1]);
}

// Shards share the workspace lock and each holds its own: two shards run
// side by side, a second process of one shard and an unsharded run do not.
TEST(WorkspaceLockTest, ShardsShareTheWorkspaceLockAndEachHoldsItsOwn) {
  test::TempDir dir;
  const std::string stereo = dir / "stereo";
  WorkspaceLock shared_a(stereo, kWorkspaceLockName, LockMode::kShared);
  WorkspaceLock shard_a(stereo, "msp_stereo.shard-0-of-2.lock");
  WorkspaceLock shared_b(stereo, kWorkspaceLockName, LockMode::kShared);
  WorkspaceLock shard_b(stereo, "msp_stereo.shard-1-of-2.lock");
  try {
    WorkspaceLock again(stereo, "msp_stereo.shard-1-of-2.lock");
    FAIL() << "a second process of shard 1/2 was let in";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(stereo + "/msp_stereo.shard-1-of-2.lock"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(WorkspaceLock unsharded(stereo), InputError);
}

TEST(WorkspaceLockTest, AnUnshardedRunKeepsShardsOut) {
  test::TempDir dir;
  const std::string stereo = dir / "stereo";
  WorkspaceLock unsharded(stereo);
  EXPECT_THROW(WorkspaceLock shard(stereo, kWorkspaceLockName, LockMode::kShared), InputError);
}

TEST(WorkspaceLockTest, AnUncreatableLockFileIsNamed) {
  test::TempDir dir;
  test::WriteRaw(dir / "stereo", "a file where the folder should be");
  try {
    WorkspaceLock lock(dir / "stereo");
    FAIL() << "locked inside a file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(dir / "stereo"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace msp

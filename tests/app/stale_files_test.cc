#include "app/stale_files.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "io/errors.h"
#include "io/file_util.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

namespace fs = std::filesystem;

TEST(StaleFilesTest, Names) {
  EXPECT_TRUE(IsTemporaryFileName("a.png.geometric.bin.tmp-1234"));
  EXPECT_FALSE(IsTemporaryFileName("a.png.geometric.bin"));
  EXPECT_FALSE(IsTemporaryFileName("a.tmp-"));
  EXPECT_FALSE(IsTemporaryFileName("a.tmp-12x"));
  EXPECT_FALSE(IsTemporaryFileName(".tmp-12"));
  EXPECT_TRUE(IsSpilledStateFileName("state-1234-7.bin"));
  EXPECT_FALSE(IsSpilledStateFileName("state-1234.bin"));
  EXPECT_FALSE(IsSpilledStateFileName("state--7.bin"));
  EXPECT_FALSE(IsSpilledStateFileName("state-1-7.bin.tmp-3"));
}

TEST(StaleFilesTest, RemovesOnlyWhatAKilledRunLeft) {
  test::TempDir dir;
  const std::string stereo = dir / "stereo", scratch = dir / "stereo/msp";
  const std::vector<std::string> stale = {stereo + "/depth_maps/sub/a.png.geometric.bin.tmp-99",
                                          stereo + "/normal_maps/a.png.photometric.bin.tmp-12",
                                          stereo + "/fusion.cfg.tmp-5",
                                          scratch + "/state-99-3.bin"};
  const std::vector<std::string> kept = {stereo + "/depth_maps/sub/a.png.geometric.bin",
                                         stereo + "/patch-match.cfg", stereo + "/msp_stereo.lock",
                                         scratch + "/notes.txt"};
  for (const std::string& path : stale) test::WriteRaw(path, "x");
  for (const std::string& path : kept) test::WriteRaw(path, "x");
  std::vector<std::string> removed = RemoveStaleFiles(stereo, scratch);
  std::vector<std::string> expected = stale;
  std::sort(removed.begin(), removed.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(removed, expected);
  for (const std::string& path : stale) EXPECT_FALSE(fs::exists(path)) << path;
  for (const std::string& path : kept) EXPECT_TRUE(fs::exists(path)) << path;
  EXPECT_TRUE(RemoveStaleFiles(dir / "missing", dir / "missing").empty());
}

// A full disk and `ulimit -f` fail the same write(2); the limit is what a
// test can set without root.
TEST(StaleFilesTest, AFailedAtomicWriteNamesTheFileAndLeavesNothing) {
  test::TempDir dir;
  const std::string path = dir / "maps/a.bin";
  test::WriteRaw(path, "old");
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = ::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = saved;
  limited.rlim_cur = 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  std::string message;
  try {
    WriteFileAtomic(path, std::string(4096, 'x'));
  } catch (const InputError& e) {
    message = e.what();
  }
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &saved), 0);
  ::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(message, "cannot write " + path + ": File too large");
  EXPECT_EQ(test::ReadRaw(path), "old");                            // the previous file is whole
  EXPECT_TRUE(RemoveStaleFiles(dir.path(), dir / "none").empty());  // no temporary left
}

}  // namespace
}  // namespace msp

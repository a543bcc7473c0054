#include "app/shard_setup.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/errors.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

// Three problems over four views: "d.png" is only a source.
Workspace SmallWorkspace() {
  Workspace workspace;
  for (const char* name : {"a.png", "b.png", "sub/c.png", "d.png"}) {
    View view;
    view.name = name;
    workspace.views.push_back(view);
  }
  for (int ref = 0; ref < 3; ++ref) {
    Problem problem;
    problem.ref = ref;
    problem.srcs = {3, (ref + 1) % 3};
    problem.depth_min = 1.0f;
    problem.depth_max = 2.5f;
    workspace.problems.push_back(problem);
  }
  return workspace;
}

TEST(ShardSetup, AnImageListNamesReferenceImages) {
  test::TempDir dir;
  test::WriteRaw(dir / "list.txt", "# mine\n  sub/c.png \n\na.png\r\na.png\n");
  EXPECT_EQ(ReadImageList(dir / "list.txt", SmallWorkspace()), (std::vector<int>{0, 2}));
}

TEST(ShardSetup, AnImageListWithAnUnknownNameOrNoNameIsRefused) {
  test::TempDir dir;
  test::WriteRaw(dir / "list.txt", "a.png\nd.png\n");
  try {
    ReadImageList(dir / "list.txt", SmallWorkspace());
    FAIL() << "a source-only image was taken as a reference image";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("--MspStereo.image_list " + dir / "list.txt" + " line 2: `d.png`"),
              std::string::npos)
        << message;
  }
  test::WriteRaw(dir / "empty.txt", "# nothing\n\n");
  EXPECT_THROW(ReadImageList(dir / "empty.txt", SmallWorkspace()), InputError);
  EXPECT_THROW(ReadImageList(dir / "missing.txt", SmallWorkspace()), InputError);
}

TEST(ShardSetup, ShardsOwnEveryNthProblemAndHaveTheirOwnNames) {
  MspStereoOptions msp;
  EXPECT_FALSE(IsSharded(msp));
  msp.shard = "1/2";
  EXPECT_TRUE(IsSharded(msp));
  EXPECT_EQ(OwnedProblems(msp, SmallWorkspace()), (std::vector<int>{1}));
  EXPECT_EQ(ShardName(msp), "shard 1/2");
  EXPECT_EQ(ShardTag(msp), "shard-1-of-2");
  msp.shard = "";
  msp.image_list = "/x/y/mine.txt";
  EXPECT_EQ(ShardName(msp), "image list /x/y/mine.txt");
  EXPECT_EQ(ShardTag(msp), "list-mine.txt");
}

// Every process of a run must agree on what decides the maps, wherever the
// workspace is mounted and however many threads and which shard each has.
TEST(ShardSetup, TheFingerprintIgnoresWhatLeavesTheMapsAlone) {
  StereoCommandOptions a;
  a.workspace_path = "/mnt/a";
  a.msp.shard = "0/3";
  StereoCommandOptions b = a;
  b.workspace_path = "/nfs/b";
  b.msp.shard = "2/3";
  b.patch_match.num_threads = 8;
  b.msp.shard_timeout = 60;
  b.log_level = 0;
  const Workspace workspace = SmallWorkspace();
  const std::string fingerprint = SharedRunFingerprint(a, workspace);
  EXPECT_EQ(SharedRunFingerprint(b, workspace), fingerprint);
  EXPECT_NE(fingerprint.find("problem sub/c.png <- d.png a.png depth 1 2.5\n"), std::string::npos)
      << fingerprint;
  b.random_seed = 1;
  EXPECT_NE(SharedRunFingerprint(b, workspace), fingerprint);
  Workspace other = workspace;
  other.problems[0].srcs = {3};
  EXPECT_NE(SharedRunFingerprint(a, other), fingerprint);
}

}  // namespace
}  // namespace msp

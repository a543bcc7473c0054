#include "app/shared_pass_dir.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/errors.h"
#include "io/file_util.h"
#include "tests/support/files.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace {

const std::vector<std::string> kNames = {"a.png", "sub/b.png"};

PixelState SmallState(float depth) {
  PixelState state(2, 2);
  state.depth.assign(4, depth);
  state.classes.assign(4, 1);
  return state;
}

TEST(SharedPassDir, SavesLoadsAndRemovesStatesUnderTheImageNames) {
  test::TempDir dir;
  SharedPassDir shared(dir / "msp_shared", kNames, "options\n");
  EXPECT_FALSE(shared.Has(3, 1));
  shared.Save(3, 1, SmallState(2.5f));
  EXPECT_EQ(shared.StatePath(3, 1), dir / "msp_shared/pass_03/sub/b.png.state");
  EXPECT_TRUE(IsFile(shared.StatePath(3, 1)));
  EXPECT_TRUE(shared.Has(3, 1));
  const PixelState back = shared.Load(3, 1);
  EXPECT_EQ(back.depth, SmallState(2.5f).depth);
  EXPECT_EQ(back.classes, SmallState(2.5f).classes);
  shared.Remove(3, 1);
  EXPECT_FALSE(shared.Has(3, 1));
  shared.Remove(3, 1);  // gone already: no error
  shared.Save(0, 0, SmallState(1.0f));
  shared.Clear();
  EXPECT_FALSE(IsDirectory(dir / "msp_shared"));
}

TEST(SharedPassDir, ACorruptStateIsNamed) {
  test::TempDir dir;
  SharedPassDir shared(dir / "msp_shared", kNames, "options\n");
  shared.Save(1, 0, SmallState(1.0f));
  test::WriteRaw(shared.StatePath(1, 0), "not a state");
  try {
    shared.Load(1, 0);
    FAIL() << "a corrupt state was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(shared.StatePath(1, 0)), std::string::npos) << e.what();
  }
}

TEST(SharedPassDir, RefusesTheStatesOfARunWithOtherOptions) {
  test::TempDir dir;
  { SharedPassDir first(dir / "msp_shared", kNames, "--a 1\n--seed 0\n"); }
  EXPECT_NO_THROW(SharedPassDir same(dir / "msp_shared", kNames, "--a 1\n--seed 0\n"));
  try {
    SharedPassDir other(dir / "msp_shared", kNames, "--a 1\n--seed 3\n");
    FAIL() << "another run's states were taken";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("line 2: this run has `--seed 3`, that run `--seed 0`"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("delete " + dir / "msp_shared"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace msp

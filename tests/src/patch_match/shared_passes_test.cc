#include "patch_match/shared_passes.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/memory_exchange.h"

namespace msp {
namespace {

// Four views, each a problem with the other three as sources; shard 0/2
// owns problems 0 and 2.
struct Fixture {
  Fixture() {
    for (int v = 0; v < 4; ++v) {
      View view;
      view.name = "img_" + std::to_string(v) + ".png";
      views.push_back(view);
      Problem problem;
      problem.ref = v;
      for (int s = 0; s < 4; ++s) {
        if (s != v) problem.srcs.push_back(s);
      }
      problems.push_back(problem);
    }
    run.exchange = &exchange;
    run.owned = {0, 2};
    run.shard = ShardSpec{0, 2};
    run.timeout_seconds = 0.3;
    run.name = "shard 0/2";
  }

  void SaveAll(int pass, std::vector<int> view_list) {
    for (int v : view_list) {
      PixelState state(3, 2);
      state.depth.assign(6, 1.0f + v + 10.0f * pass);
      exchange.Save(pass, v, state);
    }
  }

  std::vector<View> views;
  std::vector<Problem> problems;
  test::MemoryExchange exchange;
  SharedRun run;
};

TEST(SharedPasses, ResumesAfterTheLastPassWithEveryOwnedState) {
  Fixture f;
  SharedPasses shared(f.run, f.views, f.problems);
  EXPECT_EQ(shared.LastSavedPass(5), -1);
  f.SaveAll(0, {0, 1, 2, 3});
  f.SaveAll(1, {0, 1, 2});
  f.SaveAll(2, {0});  // a crash between the two images of pass 2
  EXPECT_EQ(shared.LastSavedPass(5), 1);
}

TEST(SharedPasses, PassesWhenEveryImageIsDoneAndDropsItsOwnOlderStates) {
  Fixture f;
  SharedPasses shared(f.run, f.views, f.problems);
  f.SaveAll(0, {0, 1, 2, 3});
  f.SaveAll(1, {0, 1, 2, 3});
  shared.WaitForPass(1, "pass 2");
  // Pass 0's states of the owned images are gone, the other shard's stay
  // for it to drop.
  EXPECT_FALSE(f.exchange.Has(0, 0));
  EXPECT_FALSE(f.exchange.Has(0, 2));
  EXPECT_TRUE(f.exchange.Has(0, 1));
  EXPECT_TRUE(f.exchange.Has(1, 0));
}

TEST(SharedPasses, TimesOutNamingTheMissingImagesAndTheirShards) {
  Fixture f;
  SharedPasses shared(f.run, f.views, f.problems);
  f.SaveAll(3, {0, 2});
  try {
    shared.WaitForPass(3, "round 1/1, geometric pass 4");
    FAIL() << "the barrier passed without images 1 and 3";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("shard 0/2: waited 0 s (--MspStereo.shard_timeout) for 2 image(s) "
                           "to finish round 1/1, geometric pass 4 in memory: img_1.png (shard "
                           "1/2), img_3.png (shard 1/2)"),
              std::string::npos)
        << message;
  }
}

TEST(SharedPasses, ReadsOnlyTheSourcesOfOtherProcesses) {
  Fixture f;
  SharedPasses shared(f.run, f.views, f.problems);
  f.SaveAll(4, {1, 3});  // the owned images' states are in memory, not here
  std::map<int, DenseMap> depths;
  depths[0] = DenseMap(3, 2, 1);
  depths[2] = DenseMap(3, 2, 1);
  shared.AddSourceDepths(4, {0, 1, 2, 3}, &depths);
  ASSERT_EQ(depths.size(), 4u);
  EXPECT_EQ(depths.at(1).data[0], 42.0f);
  EXPECT_EQ(depths.at(3).data[5], 44.0f);
  EXPECT_EQ(depths.at(0).data[0], 0.0f);
}

TEST(SharedPasses, ClearsOnlyWhenEveryImageHasItsFinalMaps) {
  Fixture f;
  SharedPasses shared(f.run, f.views, f.problems);
  f.SaveAll(0, {0, 1});
  EXPECT_FALSE(shared.ClearWhenComplete([](int view) { return view != 3; }));
  EXPECT_EQ(f.exchange.Size(), 2u);
  EXPECT_TRUE(shared.ClearWhenComplete([](int) { return true; }));
  EXPECT_EQ(f.exchange.Size(), 0u);
}

}  // namespace
}  // namespace msp

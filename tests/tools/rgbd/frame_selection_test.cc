#include "tools/rgbd/frame_selection.h"

#include <gtest/gtest.h>

#include "io/errors.h"

namespace msp {
namespace rgbd {
namespace {

// Ten frames 0.1 m apart along x.
std::vector<Eigen::Vector3d> Line() {
  std::vector<Eigen::Vector3d> centers;
  for (int i = 0; i < 10; ++i) centers.emplace_back(0.1 * i, 0.0, 0.0);
  return centers;
}

std::vector<int> Select(const std::string& frames, int step = 1, double baseline = 0.0) {
  return SelectFrames(Line(), FrameSelection{frames, step, baseline});
}

TEST(SelectFrames, RangesStepsAndBaselines) {
  EXPECT_EQ(Select(""), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(Select("0-2,7-9"), (std::vector<int>{0, 1, 2, 7, 8, 9}));
  EXPECT_EQ(Select("1, 4 - 5"), (std::vector<int>{1, 4, 5}));
  // The step restarts at each range's first frame.
  EXPECT_EQ(Select("0-4,6-9", 3), (std::vector<int>{0, 3, 6, 9}));
  // 0.25 m: each kept frame is at least that far from the one kept before.
  EXPECT_EQ(Select("", 1, 0.25), (std::vector<int>{0, 3, 6, 9}));
}

TEST(SelectFrames, BadSelectionsNameTheOption) {
  for (const char* frames : {"3-1", "0-10", "x", "1-", "0-3,2-5", "5,1", "-2"}) {
    EXPECT_THROW(Select(frames), InputError) << frames;
  }
  EXPECT_THROW(Select("", 0), InputError);
  EXPECT_THROW(Select("", 1, -1.0), InputError);
  EXPECT_THROW(Select("4"), InputError);         // one frame cannot triangulate
  EXPECT_THROW(Select("", 1, 5.0), InputError);  // the baseline keeps one frame
}

}  // namespace
}  // namespace rgbd
}  // namespace msp

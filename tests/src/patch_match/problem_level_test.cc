#include "patch_match/problem_level.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "patch_match/image_pyramid.h"
#include "tests/support/synthetic_views.h"

namespace msp {
namespace {

// 50x38 halves to 25x19, then to 12x9 (odd sizes drop the last row/column).
std::vector<View> ThreeViews() { return test::RenderFrontoParallelPlane(50, 38, 3, 2.0f, 0.25f); }

TEST(ProblemLevel, CamerasAndImagesAreThoseOfThePyramid) {
  const std::vector<View> views = ThreeViews();
  const Level level = BuildLevel(views, {0, 2}, /*color_view=*/0, /*halvings=*/2);
  EXPECT_EQ(level.gray.size(), 2u);
  EXPECT_EQ(level.color.size(), 1u);
  EXPECT_FALSE(level.gray.count(1));
  const DenseMap expected = DownsampleHalf(DownsampleHalf(views[2].gray));
  EXPECT_EQ(level.gray.at(2).data, expected.data);
  EXPECT_EQ(level.gray.at(2).width, 12);
  EXPECT_EQ(level.color.at(0).data, DownsampleHalf(DownsampleHalf(views[0].color)).data);
  core::Camera camera = views[2].camera;
  camera = HalveCamera(camera, 25, 19);
  camera = HalveCamera(camera, 12, 9);
  const core::Camera& got = level.cameras.at(2);
  EXPECT_EQ(got.width, 12);
  EXPECT_EQ(got.height, 9);
  EXPECT_FLOAT_EQ(got.fx, camera.fx);
  EXPECT_FLOAT_EQ(got.cx, camera.cx);
  EXPECT_FLOAT_EQ(got.cy, camera.cy);
  EXPECT_FLOAT_EQ(LevelCamera(views[2], 2).fy, camera.fy);
}

// `views` without their colour images (and, unless keep_gray, their grey
// ones), which load_images gives back; it counts its calls per view in
// `loads` and the grey images it gave in `gray_loads`.
std::vector<View> LoadedOnDemand(const std::vector<View>& views, bool keep_gray,
                                 std::vector<int>* loads, int* gray_loads) {
  std::vector<View> on_demand = views;
  loads->assign(views.size(), 0);
  *gray_loads = 0;
  for (size_t v = 0; v < views.size(); ++v) {
    if (!keep_gray) on_demand[v].gray = DenseMap();
    on_demand[v].color = DenseMap();
    on_demand[v].load_images = [&views, loads, gray_loads, v](DenseMap* gray, DenseMap* color) {
      ++(*loads)[v];
      if (gray != nullptr) {
        ++*gray_loads;
        *gray = views[v].gray;
      }
      if (color != nullptr) *color = views[v].color;
    };
  }
  return on_demand;
}

TEST(ProblemLevel, ImagesNotInMemoryAreReadOnceEachAndGiveTheSameLevel) {
  const std::vector<View> views = ThreeViews();
  std::vector<int> loads;
  int gray_loads = 0;
  const std::vector<View> on_demand = LoadedOnDemand(views, false, &loads, &gray_loads);
  const Level a = BuildLevel(views, {1, 0}, 1, 1);
  const Level b = BuildLevel(on_demand, {1, 0}, 1, 1);
  EXPECT_EQ(loads, (std::vector<int>{1, 1, 0}));
  EXPECT_EQ(gray_loads, 2);
  EXPECT_EQ(a.gray.at(0).data, b.gray.at(0).data);
  EXPECT_EQ(a.gray.at(1).data, b.gray.at(1).data);
  EXPECT_EQ(a.color.at(1).data, b.color.at(1).data);
  // The views keep nothing of what was read.
  EXPECT_TRUE(on_demand[0].gray.Empty());
}

// A view that holds its grey image but not its colour (an image kept as
// its 8-bit pixels) has only the colour loaded, and only as the reference.
TEST(ProblemLevel, AViewHoldingItsGreyHasOnlyItsColourLoaded) {
  const std::vector<View> views = ThreeViews();
  std::vector<int> loads;
  int gray_loads = 0;
  const std::vector<View> grey_kept = LoadedOnDemand(views, true, &loads, &gray_loads);
  const Level a = BuildLevel(views, {1, 0}, 1, 1);
  const Level b = BuildLevel(grey_kept, {1, 0}, 1, 1);
  EXPECT_EQ(loads, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(gray_loads, 0);
  EXPECT_EQ(a.gray.at(0).data, b.gray.at(0).data);
  EXPECT_EQ(a.color.at(1).data, b.color.at(1).data);
}

TEST(ProblemLevel, ColourOfAnotherSizeIsRefusedNamingTheView) {
  std::vector<View> views = ThreeViews();
  views[1].color = DenseMap(10, 10, 3);
  EXPECT_NO_THROW(BuildLevel(views, {1}, -1, 0));
  try {
    BuildLevel(views, {1}, 1, 0);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("view_1.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace msp

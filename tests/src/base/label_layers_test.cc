#include "base/label_layers.h"

#include <gtest/gtest.h>

#include <vector>

namespace msp {
namespace {

TEST(LabelLayers, NearestUpsamplingRepeatsLabels) {
  const std::vector<int32_t> labels = {1, 2,  //
                                       3, 4};
  EXPECT_EQ(ResampleLabelsNearest(labels, 2, 2, 4, 4), (std::vector<int32_t>{1, 1, 2, 2,  //
                                                                             1, 1, 2, 2,  //
                                                                             3, 3, 4, 4,  //
                                                                             3, 3, 4, 4}));
}

TEST(LabelLayers, NearestDownsamplingPicksThePixelUnderTheCentreAndNeverBlends) {
  const std::vector<int32_t> labels = {1, 2, 3, 4,  5,  6,  //
                                       7, 8, 9, 10, 11, 12};
  // 6 -> 3 columns: centres at 1, 3, 5; 2 -> 1 rows: centre at row 1.
  EXPECT_EQ(ResampleLabelsNearest(labels, 6, 2, 3, 1), (std::vector<int32_t>{8, 10, 12}));
  EXPECT_EQ(ResampleLabelsNearest(labels, 6, 2, 6, 2), labels);
}

TEST(LabelLayers, ResampleEveryLevel) {
  LabelLayers layers;
  layers.width = 2;
  layers.height = 1;
  layers.levels = {{1, 2}, {5, 5}};
  const LabelLayers out = ResampleNearest(layers, 4, 3);
  ASSERT_EQ(out.NumLevels(), 2);
  EXPECT_EQ(out.width, 4);
  EXPECT_EQ(out.height, 3);
  EXPECT_EQ(out.At(0, 2, 1), 1);
  EXPECT_EQ(out.At(0, 1, 2), 2);
  EXPECT_EQ(out.levels[1], std::vector<int32_t>(12, 5));
}

}  // namespace
}  // namespace msp

#include "prior/graph_segmentation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include "prior/multiscale_segmentation.h"
#include "tests/support/colour_images.h"

namespace msp {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr Segmenter kSegmenters[] = {Segmenter::kOpenCv, Segmenter::kEmbedded};

// Pixels per region id; fails unless the ids are exactly 1..K.
std::map<int32_t, int> RegionSizes(const std::vector<int32_t>& labels) {
  std::map<int32_t, int> sizes;
  for (int32_t id : labels) ++sizes[id];
  EXPECT_EQ(sizes.begin()->first, 1);
  EXPECT_EQ(sizes.rbegin()->first, static_cast<int32_t>(sizes.size()));
  return sizes;
}

TEST(GraphSegmentation, SegmenterNamesRoundTripAndUnknownNamesAreRefused) {
  for (Segmenter s : kSegmenters) EXPECT_EQ(SegmenterFromName(SegmenterName(s)), s);
  EXPECT_THROW(SegmenterFromName("fast"), std::invalid_argument);
  EXPECT_THROW(SegmenterFromName("OpenCV"), std::invalid_argument);
}

// Both segmenters give ids 1..K, regions of at least min_size pixels, and
// one region on each side of a colour edge. (The smoothing leaves strips of
// mixed colour along the edge, one pixel wide and as long as the image, which
// OpenCV's 4-connected grid keeps as regions of their own.)
TEST(GraphSegmentation, BothSegmentersGiveValidLabelMaps) {
  constexpr int kEdge = 40, kStrip = 2;
  const DenseMap image = test::TwoColourImage(kWidth, kHeight, kEdge, {0.7f, 0.3f, 0.2f},
                                              {0.2f, 0.3f, 0.7f}, 0.02f, 5);
  const GraphSegmentationScale scale = SegmentationScale(0, 3, kWidth, kHeight);
  for (Segmenter s : kSegmenters) {
    SCOPED_TRACE(SegmenterName(s));
    const std::vector<int32_t> labels = SegmentGraph(image, scale, s);
    ASSERT_EQ(labels.size(), static_cast<size_t>(kWidth * kHeight));
    const std::map<int32_t, int> sizes = RegionSizes(labels);
    EXPECT_LE(sizes.size(), 2u + 2 * kStrip);
    for (const auto& region : sizes) EXPECT_GE(region.second, scale.min_size);
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        if (col < kEdge - kStrip) {
          EXPECT_EQ(labels[row * kWidth + col], labels[0]);
        }
        if (col >= kEdge + kStrip) {
          EXPECT_EQ(labels[row * kWidth + col], labels[kWidth - 1]);
        }
      }
    }
    EXPECT_NE(labels[0], labels[kWidth - 1]);
  }
}

// A feature image of any channel count: one channel with a step, no
// smoothing, one segmentation per scale; min_size merges the small block.
TEST(GraphSegmentation, FeatureImagesOfAnyChannelCountAtSeveralScales) {
  DenseMap features(kWidth, kHeight, 1, 0.0f);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      features.At(row, col) = (col >= 32 ? 10.0f : 0.0f) + (row < 2 && col < 2 ? 5.0f : 0.0f);
    }
  }
  const std::vector<GraphSegmentationScale> scales = {{1.0f, 1}, {1.0f, 16}};
  for (Segmenter s : kSegmenters) {
    SCOPED_TRACE(SegmenterName(s));
    const std::vector<std::vector<int32_t>> levels =
        SegmentFeatureImage(features, FeatureSmoothing{0.0f, 1.0f}, scales, s);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(RegionSizes(levels[0]).size(), 3u);  // left, right, the 2x2 block
    const std::map<int32_t, int> merged = RegionSizes(levels[1]);
    ASSERT_EQ(merged.size(), 2u);
    EXPECT_EQ(merged.begin()->second, 32 * kHeight);
    EXPECT_EQ(levels[1][0], levels[1][kWidth + 5]);  // the block joined the left side
  }
}

TEST(GraphSegmentation, Deterministic) {
  const DenseMap image =
      test::TwoColourImage(kWidth, kHeight, 20, {0.5f, 0.5f, 0.5f}, {0.45f, 0.5f, 0.55f}, 0.1f, 9);
  const GraphSegmentationScale scale = SegmentationScale(2, 3, kWidth, kHeight);
  for (Segmenter s : kSegmenters) {
    EXPECT_EQ(SegmentGraph(image, scale, s), SegmentGraph(image, scale, s)) << SegmenterName(s);
  }
}

}  // namespace
}  // namespace msp

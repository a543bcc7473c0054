#include "prior/multiscale_segmentation.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <vector>

#include "core/math/rng.h"
#include "tests/support/colour_images.h"

namespace msp {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
// Per-channel noise amplitude on [0, 1] colours: sensor-like, far below the
// colour steps of the test images.
constexpr float kNoise = 0.02f;
constexpr uint32_t kNoiseSeed = 7;

// Left half red, right half blue, with a little noise.
DenseMap RedBlueImage() {
  return test::TwoColourImage(kWidth, kHeight, kWidth / 2, {0.8f, 0.2f, 0.1f}, {0.1f, 0.2f, 0.8f},
                              kNoise, kNoiseSeed);
}

// 8x6 blocks of 8x8 pixels with colours whose contrast to their neighbours
// varies, so coarser scales merge more of them.
DenseMap BlockImage() {
  DenseMap image(kWidth, kHeight, 3);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const int block = (row / 8) * 8 + col / 8;
      for (int c = 0; c < 3; ++c) {
        image.At(row, col, c) = core::RandomUniform(core::RngKey(3, 0, 0, 0, block), c) * 0.5f +
                                0.25f + test::PixelNoise(kNoiseSeed, row * kWidth + col, c, kNoise);
      }
    }
  }
  return image;
}

int CountRegions(const std::vector<int32_t>& labels) {
  return static_cast<int>(std::set<int32_t>(labels.begin(), labels.end()).size());
}

TEST(MultiscaleSegmentation, NoRegionCrossesAColourEdge) {
  const LabelLayers layers = SegmentMultiscale(RedBlueImage(), 3, Segmenter::kEmbedded);
  ASSERT_EQ(layers.NumLevels(), 3);
  EXPECT_EQ(layers.width, kWidth);
  EXPECT_EQ(layers.height, kHeight);
  // The smoothed edge leaves thin strips of mixed colour along it, which only
  // min_size merges at full resolution; away from it each side is one region.
  constexpr int kStrip = 2;
  for (int n = 0; n < 3; ++n) {
    std::set<int32_t> left, right;
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        (col < kWidth / 2 ? left : right).insert(layers.At(n, row, col));
        if (col < kWidth / 2 - kStrip) {
          EXPECT_EQ(layers.At(n, row, col), layers.At(n, 0, 0));
        }
        if (col >= kWidth / 2 + kStrip) {
          EXPECT_EQ(layers.At(n, row, col), layers.At(n, 0, kWidth - 1));
        }
      }
    }
    for (int32_t id : left) EXPECT_EQ(right.count(id), 0u) << "level " << n << " region " << id;
    EXPECT_EQ(layers.At(n, 0, 0), 1);  // ids 1..K in raster order, never 0
  }
}

TEST(MultiscaleSegmentation, FinerLevelsHaveMoreRegions) {
  const LabelLayers layers = SegmentMultiscale(BlockImage(), 3, Segmenter::kEmbedded);
  const int coarse = CountRegions(layers.levels[0]);
  const int middle = CountRegions(layers.levels[1]);
  const int fine = CountRegions(layers.levels[2]);
  EXPECT_LT(coarse, middle);
  EXPECT_LE(middle, fine);
  EXPECT_GE(fine, 20);  // most of the 48 blocks are separated
}

TEST(MultiscaleSegmentation, DeterministicAndEqualToTheSingleScaleCall) {
  const DenseMap image = BlockImage();
  const LabelLayers a = SegmentMultiscale(image, 3, Segmenter::kEmbedded);
  const LabelLayers b = SegmentMultiscale(image, 3, Segmenter::kEmbedded);
  EXPECT_EQ(a.levels, b.levels);
  EXPECT_EQ(a.levels[1], SegmentGraph(image, SegmentationScale(1, 3, kWidth, kHeight), Segmenter::kEmbedded));
}

TEST(MultiscaleSegmentation, ScalesGoFromCoarseToFineAndFollowTheImageArea) {
  const GraphSegmentationScale coarse = SegmentationScale(0, 3, 640, 480);
  const GraphSegmentationScale middle = SegmentationScale(1, 3, 640, 480);
  const GraphSegmentationScale fine = SegmentationScale(2, 3, 640, 480);
  EXPECT_GT(coarse.k, middle.k);
  EXPECT_GT(middle.k, fine.k);
  EXPECT_GT(coarse.min_size, middle.min_size);
  EXPECT_GT(middle.min_size, fine.min_size);
  const GraphSegmentationScale big = SegmentationScale(0, 3, 1280, 960);
  EXPECT_FLOAT_EQ(big.k, 4.0f * coarse.k);
  EXPECT_FLOAT_EQ(SegmentationScale(0, 3, 64, 48).k, coarse.k);  // not below the reference
  EXPECT_GE(SegmentationScale(2, 3, 8, 8).min_size, 1);
}

}  // namespace
}  // namespace msp

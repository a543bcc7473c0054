#include "prior/crf_refinement.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/math/rng.h"
#include "tests/support/colour_images.h"

namespace msp {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr int kEdgeCol = 32;  // true depth edge: columns < 32 near, >= 32 far
constexpr float kNearDepth = 1.0f;
constexpr float kFarDepth = 2.0f;
constexpr float kDepthMin = 0.5f;
constexpr float kDepthMax = 2.5f;
// The aggregated segmentation puts the edge 2 px too far left and has 5 %
// of its labels flipped at random.
constexpr int kWrongEdgeCol = 30;
constexpr float kLabelNoise = 0.05f;
constexpr float kColorNoise = 0.03f;
constexpr uint32_t kSeed = 11;

// Same grey-ish colour on both sides (a depth edge the colour cannot see),
// or a colour edge at `color_edge_col` when it is inside the image.
DenseMap Colors(int color_edge_col) {
  return test::TwoColourImage(kWidth, kHeight, color_edge_col, {0.6f, 0.5f, 0.2f},
                              {0.2f, 0.5f, 0.6f}, kColorNoise, kSeed);
}

DenseMap Depths() {
  DenseMap depth(kWidth, kHeight, 1);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      depth.At(row, col) = col < kEdgeCol ? kNearDepth : kFarDepth;
    }
  }
  return depth;
}

Segmentation NoisyLabels() {
  Segmentation seg;
  seg.width = kWidth;
  seg.height = kHeight;
  seg.labels.resize(kWidth * kHeight);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const int i = row * kWidth + col;
      const int32_t label = col < kWrongEdgeCol ? 1 : 2;
      // Draw 3 of the pixel's stream: draws 0-2 are its colour noise.
      const float u = core::RandomUniform(core::RngKey(kSeed, 0, 0, 0, i), 3);
      seg.labels[i] = u < kLabelNoise ? 3 - label : label;
    }
  }
  seg.edges = ComputeBoundaryMap(seg.labels, kWidth, kHeight);
  return seg;
}

// Pixels whose label is not that of a clean split at `edge_col`.
int Mislabelled(const Segmentation& seg, int edge_col) {
  int wrong = 0;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      wrong += seg.labels[row * kWidth + col] != (col < edge_col ? 1 : 2);
    }
  }
  return wrong;
}

TEST(CrfRefinement, DepthMovesTheBoundaryToTheTrueDepthEdgeAndRemovesNoise) {
  const Segmentation noisy = NoisyLabels();
  ASSERT_GT(Mislabelled(noisy, kEdgeCol), 2 * kHeight);
  const DenseMap depth = Depths();
  const Segmentation refined = RefineSegmentationCrf(noisy, Colors(/*color_edge_col=*/kWidth),
                                                     &depth, kDepthMin, kDepthMax, CrfOptions());
  EXPECT_EQ(Mislabelled(refined, kEdgeCol), 0);
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const bool on_edge = col == kEdgeCol - 1 || col == kEdgeCol;
      EXPECT_EQ(refined.edges[row * kWidth + col], on_edge ? 1 : 0) << col << "," << row;
    }
  }
}

TEST(CrfRefinement, WithoutDepthTheColourEdgeGuides) {
  const Segmentation refined =
      RefineSegmentationCrf(NoisyLabels(), Colors(/*color_edge_col=*/kEdgeCol), nullptr, kDepthMin,
                            kDepthMax, CrfOptions());
  EXPECT_EQ(Mislabelled(refined, kEdgeCol), 0);
  const DenseMap empty;
  EXPECT_EQ(RefineSegmentationCrf(NoisyLabels(), Colors(kEdgeCol), &empty, kDepthMin, kDepthMax,
                                  CrfOptions())
                .labels,
            refined.labels);
}

TEST(CrfRefinement, WithNoEvidenceTheBoundaryStaysAndNoiseGoes) {
  const Segmentation refined = RefineSegmentationCrf(NoisyLabels(), Colors(kWidth), nullptr,
                                                     kDepthMin, kDepthMax, CrfOptions());
  // Nothing tells where the boundary belongs: it stays, up to a pixel of
  // wiggle where label noise touched it; the noise elsewhere is gone.
  int wiggle = 0;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const bool wrong = refined.labels[row * kWidth + col] != (col < kWrongEdgeCol ? 1 : 2);
      if (col == kWrongEdgeCol - 1 || col == kWrongEdgeCol) {
        wiggle += wrong;
      } else {
        EXPECT_FALSE(wrong) << col << "," << row;
      }
    }
  }
  EXPECT_LE(wiggle, kHeight / 8);
}

TEST(CrfRefinement, InvalidDepthFallsBackToColourPerPair) {
  DenseMap depth = Depths();
  std::fill(depth.data.begin(), depth.data.end(), 0.0f);
  const Segmentation with_zero_depth = RefineSegmentationCrf(
      NoisyLabels(), Colors(kEdgeCol), &depth, kDepthMin, kDepthMax, CrfOptions());
  EXPECT_EQ(Mislabelled(with_zero_depth, kEdgeCol), 0);
}

TEST(CrfRefinement, SameResultForAnyThreadCount) {
  const DenseMap depth = Depths();
  CrfOptions options;
  options.num_threads = 1;
  const Segmentation one =
      RefineSegmentationCrf(NoisyLabels(), Colors(kWidth), &depth, kDepthMin, kDepthMax, options);
  options.num_threads = 2;
  EXPECT_EQ(one.labels, RefineSegmentationCrf(NoisyLabels(), Colors(kWidth), &depth, kDepthMin,
                                              kDepthMax, options)
                            .labels);
}

}  // namespace
}  // namespace msp

#include "core/prior/segment_crossing.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tests/support/images.h"

namespace msp {
namespace core {
namespace {

constexpr int kSize = 16;

using test::EdgeMap;

// The subset of anchors 0..num_anchors-1 whose line from p crosses no
// boundary of `boundary`, one walk per anchor and layer (bit i = anchor i).
uint32_t AdmissibleAnchors(const BoundaryView& boundary, int p_col, int p_row,
                           const int* anchor_cols, const int* anchor_rows, int num_anchors) {
  uint32_t subset = 0u;
  for (int i = 0; i < num_anchors; ++i) {
    if (!SegmentCrossesBoundary(boundary, p_col, p_row, anchor_cols[i], anchor_rows[i])) {
      subset |= 1u << i;
    }
  }
  return subset;
}

TEST(SegmentCrossing, AnchorBehindEdgeIsRejectedAnchorInsideIsKept) {
  const EdgeMap b = test::VerticalEdge(kSize, kSize, 8);
  EXPECT_TRUE(SegmentCrossesBoundary(b.View(), 4, 5, 12, 5));   // across the edge
  EXPECT_TRUE(SegmentCrossesBoundary(b.View(), 4, 2, 12, 13));  // diagonally across
  EXPECT_FALSE(SegmentCrossesBoundary(b.View(), 4, 5, 0, 5));   // same side
  EXPECT_FALSE(SegmentCrossesBoundary(b.View(), 4, 5, 7, 15));  // same side, steep line
  EXPECT_FALSE(SegmentCrossesBoundary(b.View(), 12, 0, 15, 15));
}

TEST(SegmentCrossing, CentreOnEdgeIsNotTestedAnchorOnEdgeIs) {
  const EdgeMap b = test::VerticalEdge(kSize, kSize, 8);
  EXPECT_FALSE(SegmentCrossesBoundary(b.View(), 8, 5, 4, 5));  // p on the edge, leaving it inward
  EXPECT_TRUE(SegmentCrossesBoundary(b.View(), 4, 5, 8, 5));   // anchor on the edge
  EXPECT_FALSE(SegmentCrossesBoundary(b.View(), 4, 5, 4, 5));  // s == p
}

TEST(SegmentCrossing, DiagonalLineCannotSlipThroughAThinDiagonalEdge) {
  // An anti-diagonal one-pixel edge: 8-connected, like a line drawn by Bresenham.
  EdgeMap b = test::NoEdges(kSize, kSize);
  for (int i = 0; i < kSize; ++i) b.bits[i * kSize + (kSize - 1 - i)] = 1;
  // The main diagonal meets the anti-diagonal between pixels for an even size;
  // a Bresenham step moves in both axes at once and could jump over it, so the
  // two-pixel-thick edges of ComputeBoundaryMap are what confinement relies on.
  EdgeMap thick = b;
  for (int i = 0; i + 1 < kSize; ++i) thick.bits[i * kSize + (kSize - 2 - i)] = 1;
  EXPECT_TRUE(SegmentCrossesBoundary(thick.View(), 0, 0, 15, 15));
}

TEST(SegmentCrossing, OutsideTheImageCountsAsBoundary) {
  const EdgeMap b = test::NoEdges(kSize, kSize);
  EXPECT_TRUE(SegmentCrossesBoundary(b.View(), 4, 4, kSize, 4));
  EXPECT_FALSE(SegmentCrossesBoundary(b.View(), 4, 4, kSize - 1, 4));
}

TEST(SegmentCrossing, OneWalkPerAnchorEqualsOneWalkPerLayer) {
  // Three layers: a vertical edge, a horizontal edge, none.
  const EdgeMap vertical = test::VerticalEdge(kSize, kSize, 8);
  EdgeMap horizontal = test::NoEdges(kSize, kSize);
  const EdgeMap none = test::NoEdges(kSize, kSize);
  for (int col = 0; col < kSize; ++col) horizontal.bits[5 * kSize + col] = 1;
  std::vector<uint32_t> packed(kSize * kSize);
  for (int i = 0; i < kSize * kSize; ++i) packed[i] = vertical.bits[i] | horizontal.bits[i] << 1;
  const LayerBoundaryView layers{packed.data(), kSize, kSize, kSize};
  int cols[kMaxPriorAnchors], rows[kMaxPriorAnchors];
  for (int i = 0; i < kMaxPriorAnchors; ++i) {
    cols[i] = (i * 7) % kSize;
    rows[i] = (i * 11 + 3) % kSize;
  }
  const EdgeMap* maps[3] = {&vertical, &horizontal, &none};
  for (int p_row = 0; p_row < kSize; p_row += 3) {
    for (int p_col = 0; p_col < kSize; p_col += 2) {
      uint32_t subsets[3];
      AdmissibleAnchorsPerLayer(layers, 3, p_col, p_row, cols, rows, kMaxPriorAnchors, subsets);
      for (int n = 0; n < 3; ++n) {
        EXPECT_EQ(subsets[n],
                  AdmissibleAnchors(maps[n]->View(), p_col, p_row, cols, rows, kMaxPriorAnchors))
            << "layer " << n << " p " << p_col << "," << p_row;
      }
    }
  }
}

}  // namespace
}  // namespace core
}  // namespace msp

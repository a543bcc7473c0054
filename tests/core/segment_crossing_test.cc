#include "core/segment_crossing.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace msp {
namespace core {
namespace {

constexpr int kSize = 16;

// A kSize x kSize boundary image with a vertical edge (two pixels thick, as
// ComputeBoundaryMap marks both sides) at columns `col` and `col + 1`.
std::vector<uint8_t> VerticalEdge(int col) {
  std::vector<uint8_t> b(kSize * kSize, 0);
  for (int row = 0; row < kSize; ++row) b[row * kSize + col] = b[row * kSize + col + 1] = 1;
  return b;
}

BoundaryView View(const std::vector<uint8_t>& b) {
  return BoundaryView{b.data(), kSize, kSize, kSize};
}

TEST(SegmentCrossing, AnchorBehindEdgeIsRejectedAnchorInsideIsKept) {
  const std::vector<uint8_t> b = VerticalEdge(8);
  EXPECT_TRUE(SegmentCrossesBoundary(View(b), 4, 5, 12, 5));   // across the edge
  EXPECT_TRUE(SegmentCrossesBoundary(View(b), 4, 2, 12, 13));  // diagonally across
  EXPECT_FALSE(SegmentCrossesBoundary(View(b), 4, 5, 0, 5));   // same side
  EXPECT_FALSE(SegmentCrossesBoundary(View(b), 4, 5, 7, 15));  // same side, steep line
  EXPECT_FALSE(SegmentCrossesBoundary(View(b), 12, 0, 15, 15));
}

TEST(SegmentCrossing, CentreOnEdgeIsNotTestedAnchorOnEdgeIs) {
  const std::vector<uint8_t> b = VerticalEdge(8);
  EXPECT_FALSE(SegmentCrossesBoundary(View(b), 8, 5, 4, 5));  // p on the edge, leaving it inward
  EXPECT_TRUE(SegmentCrossesBoundary(View(b), 4, 5, 8, 5));   // anchor on the edge
  EXPECT_FALSE(SegmentCrossesBoundary(View(b), 4, 5, 4, 5));  // s == p
}

TEST(SegmentCrossing, DiagonalLineCannotSlipThroughAThinDiagonalEdge) {
  // An anti-diagonal one-pixel edge: 8-connected, like a line drawn by Bresenham.
  std::vector<uint8_t> b(kSize * kSize, 0);
  for (int i = 0; i < kSize; ++i) b[i * kSize + (kSize - 1 - i)] = 1;
  // The main diagonal meets the anti-diagonal between pixels for an even size;
  // a Bresenham step moves in both axes at once and could jump over it, so the
  // two-pixel-thick edges of ComputeBoundaryMap are what confinement relies on.
  std::vector<uint8_t> thick = b;
  for (int i = 0; i + 1 < kSize; ++i) thick[i * kSize + (kSize - 2 - i)] = 1;
  EXPECT_TRUE(SegmentCrossesBoundary(View(thick), 0, 0, 15, 15));
}

TEST(SegmentCrossing, OutsideTheImageCountsAsBoundary) {
  const std::vector<uint8_t> b(kSize * kSize, 0);
  EXPECT_TRUE(SegmentCrossesBoundary(View(b), 4, 4, kSize, 4));
  EXPECT_FALSE(SegmentCrossesBoundary(View(b), 4, 4, kSize - 1, 4));
}

TEST(SegmentCrossing, AdmissibleAnchorsIsABitSet) {
  const std::vector<uint8_t> b = VerticalEdge(8);
  const int cols[4] = {0, 12, 6, 15};
  const int rows[4] = {0, 5, 10, 15};
  EXPECT_EQ(AdmissibleAnchors(View(b), 4, 5, cols, rows, 4), 0b0101u);
  EXPECT_EQ(AdmissibleAnchors(View(b), 12, 5, cols, rows, 4), 0b1010u);
  EXPECT_EQ(AdmissibleAnchors(View(b), 4, 5, cols, rows, 0), 0u);
}

}  // namespace
}  // namespace core
}  // namespace msp

// Edge confinement of anchors (paper "Edge Aggregation"): an anchor s is kept
// for the unreliable pixel p only if the line l from p to s does not intersect
// the boundary map B, {s in S_n | l cap B_n = empty}. Host/device neutral.
#pragma once

#include <cstdint>

#include "core/hd.h"
#include "core/prior_limits.h"

namespace msp {
namespace core {

// A boundary map: nonzero = boundary pixel. Row-major, `pitch` bytes per row.
struct BoundaryView {
  const uint8_t* data;
  int width;
  int height;
  int pitch;
  MSP_HD bool At(int col, int row) const { return data[row * pitch + col] != 0; }
  MSP_HD bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height;
  }
};

// True when the Bresenham line from p to s touches a boundary pixel. p itself
// is not tested (a pixel lying on an edge still owns its region and must be
// able to leave it inward); every later pixel up to and including s is,
// because an anchor on an edge may carry the depth of either side. Pixels
// outside the image count as boundary.
MSP_HD bool SegmentCrossesBoundary(const BoundaryView& boundary, int p_col, int p_row, int s_col,
                                   int s_row) {
  const int dx = s_col > p_col ? s_col - p_col : p_col - s_col;
  const int dy = s_row > p_row ? s_row - p_row : p_row - s_row;
  const int step_x = s_col > p_col ? 1 : -1;
  const int step_y = s_row > p_row ? 1 : -1;
  int col = p_col;
  int row = p_row;
  int error = dx - dy;
  while (col != s_col || row != s_row) {
    const int twice_error = 2 * error;
    if (twice_error > -dy) {
      error -= dy;
      col += step_x;
    }
    if (twice_error < dx) {
      error += dx;
      row += step_y;
    }
    if (!boundary.Contains(col, row) || boundary.At(col, row)) return true;
  }
  return false;
}

// The subset S_n of anchors 0..num_anchors-1 (at most kMaxPriorAnchors) whose
// line from p crosses no boundary of `boundary`, as a bit set (bit i = anchor i).
MSP_HD uint32_t AdmissibleAnchors(const BoundaryView& boundary, int p_col, int p_row,
                                  const int* anchor_cols, const int* anchor_rows, int num_anchors) {
  uint32_t subset = 0u;
  for (int i = 0; i < num_anchors && i < kMaxPriorAnchors; ++i) {
    if (!SegmentCrossesBoundary(boundary, p_col, p_row, anchor_cols[i], anchor_rows[i])) {
      subset |= 1u << i;
    }
  }
  return subset;
}

// All layers' boundary maps packed into one image: bit n of a pixel = the
// pixel is on B_n. Lets one walk along p -> s test every layer at once.
struct LayerBoundaryView {
  const uint32_t* data;
  int width;
  int height;
  int pitch;
  MSP_HD uint32_t At(int col, int row) const { return data[row * pitch + col]; }
  MSP_HD bool Contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height;
  }
};

// The layers (bit n = layer n, of `all_layers`) whose boundary the Bresenham
// line p -> s touches, with the conventions of SegmentCrossesBoundary.
// Stops early once every layer is crossed.
MSP_HD uint32_t LayersCrossedBySegment(const LayerBoundaryView& boundaries, uint32_t all_layers,
                                       int p_col, int p_row, int s_col, int s_row) {
  const int dx = s_col > p_col ? s_col - p_col : p_col - s_col;
  const int dy = s_row > p_row ? s_row - p_row : p_row - s_row;
  const int step_x = s_col > p_col ? 1 : -1;
  const int step_y = s_row > p_row ? 1 : -1;
  int col = p_col;
  int row = p_row;
  int error = dx - dy;
  uint32_t crossed = 0u;
  while ((col != s_col || row != s_row) && crossed != all_layers) {
    const int twice_error = 2 * error;
    if (twice_error > -dy) {
      error -= dy;
      col += step_x;
    }
    if (twice_error < dx) {
      error += dx;
      row += step_y;
    }
    crossed |= boundaries.Contains(col, row) ? boundaries.At(col, row) : all_layers;
  }
  return crossed & all_layers;
}

// The per-layer subsets S_n of eq. 4's input, from one walk per anchor:
// subsets[n] bit i = anchor i's line from p crosses no pixel of B_n.
MSP_HD void AdmissibleAnchorsPerLayer(const LayerBoundaryView& boundaries, int num_layers,
                                      int p_col, int p_row, const int* anchor_cols,
                                      const int* anchor_rows, int num_anchors, uint32_t* subsets) {
  const uint32_t all_layers = num_layers >= 32 ? 0xFFFFFFFFu : (1u << num_layers) - 1u;
  for (int n = 0; n < num_layers; ++n) subsets[n] = 0u;
  for (int i = 0; i < num_anchors && i < kMaxPriorAnchors; ++i) {
    const uint32_t crossed = LayersCrossedBySegment(boundaries, all_layers, p_col, p_row,
                                                    anchor_cols[i], anchor_rows[i]);
    for (int n = 0; n < num_layers; ++n) {
      if (!((crossed >> n) & 1u)) subsets[n] |= 1u << i;
    }
  }
}

}  // namespace core
}  // namespace msp

// Edge confinement of anchors (docs/method.md section 4.2): an anchor s is kept
// for the unreliable pixel p only if the line l from p to s does not intersect
// the boundary map B, {s in S_n | l cap B_n = empty}. Host/device neutral.
#pragma once

#include <cstdint>

#include "core/math/hd.h"
#include "core/prior/prior_limits.h"

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

// Bresenham walk from p towards s: each Next() moves one pixel; p itself is
// never visited, s is the last pixel visited.
struct LineWalk {
  int col, row, s_col, s_row, dx, dy, step_x, step_y, error;
  MSP_HD LineWalk(int p_col, int p_row, int to_col, int to_row)
      : col(p_col),
        row(p_row),
        s_col(to_col),
        s_row(to_row),
        dx(to_col > p_col ? to_col - p_col : p_col - to_col),
        dy(to_row > p_row ? to_row - p_row : p_row - to_row),
        step_x(to_col > p_col ? 1 : -1),
        step_y(to_row > p_row ? 1 : -1),
        error(dx - dy) {}
  MSP_HD bool Done() const { return col == s_col && row == s_row; }
  MSP_HD void Next() {
    const int twice_error = 2 * error;
    if (twice_error > -dy) {
      error -= dy;
      col += step_x;
    }
    if (twice_error < dx) {
      error += dx;
      row += step_y;
    }
  }
};

// True when the Bresenham line from p to s touches a boundary pixel. p itself
// is not tested (a pixel lying on an edge still owns its region and must be
// able to leave it inward); every later pixel up to and including s is,
// because an anchor on an edge may carry the depth of either side. Pixels
// outside the image count as boundary.
MSP_HD bool SegmentCrossesBoundary(const BoundaryView& boundary, int p_col, int p_row, int s_col,
                                   int s_row) {
  for (LineWalk walk(p_col, p_row, s_col, s_row); !walk.Done();) {
    walk.Next();
    if (!boundary.Contains(walk.col, walk.row) || boundary.At(walk.col, walk.row)) return true;
  }
  return false;
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
  uint32_t crossed = 0u;
  for (LineWalk walk(p_col, p_row, s_col, s_row); !walk.Done() && crossed != all_layers;) {
    walk.Next();
    crossed |=
        boundaries.Contains(walk.col, walk.row) ? boundaries.At(walk.col, walk.row) : all_layers;
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

// The 4-neighbourhood of a pixel, clipped to the image: the walk the
// segment-plane support, its borrowed-inlier test and the open-sky outline
// share.
#pragma once

namespace msp {

// Calls `visit(col, row)` for the pixels 4-adjacent to (col, row) inside a
// width x height image, in the order left, right, up, down, until a call
// returns true; returns whether one did.
template <typename Visit>
bool VisitNeighbours4(int width, int height, int col, int row, Visit visit) {
  const int cols[4] = {col - 1, col + 1, col, col};
  const int rows[4] = {row, row, row - 1, row + 1};
  for (int k = 0; k < 4; ++k) {
    if (cols[k] < 0 || rows[k] < 0 || cols[k] >= width || rows[k] >= height) continue;
    if (visit(cols[k], rows[k])) return true;
  }
  return false;
}

}  // namespace msp

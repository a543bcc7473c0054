// Anchors of the segmentation prior's tests: two surfaces split by a depth
// edge, so that only the anchors on the pixel's own side fit its plane.
#pragma once

#include <vector>

#include "core/prior/best_layer.h"

namespace msp {
namespace test {

// Depth of the pixel's own surface: the plane z = 2.
constexpr float kNearSurfaceZ = 2.0f;

// Anchors of pixel (col, row) at the pixels (cols[i], rows[i]), with the
// points (0.1 cols[i], 0.1 rows[i], z): z = kNearSurfaceZ on the columns
// before `edge_col`, z = far_z(x, y) (the surface behind the edge) from it on.
template <typename FarZ>
core::PriorAnchors AnchorsAcrossDepthEdge(int col, int row, const std::vector<int>& cols,
                                          const std::vector<int>& rows, int edge_col, FarZ far_z) {
  core::PriorAnchors a{};
  a.col = col;
  a.row = row;
  a.count = static_cast<int>(cols.size());
  for (int i = 0; i < a.count; ++i) {
    a.cols[i] = cols[i];
    a.rows[i] = rows[i];
    const float x = 0.1f * cols[i];
    const float y = 0.1f * rows[i];
    a.points[i] = core::Vec3{x, y, cols[i] < edge_col ? kNearSurfaceZ : far_z(x, y)};
  }
  return a;
}

}  // namespace test
}  // namespace msp

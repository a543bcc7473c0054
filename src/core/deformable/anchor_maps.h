// The maps the anchor search reads (docs/method.md sections 3.2 and 4.2) and
// the edge-confinement tests on them, shared by the anchor rays (anchors.h)
// and the boundary rays of adaptive equidistribution (equidistribution.h).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/math/hd.h"
#include "core/prior/segment_crossing.h"

namespace msp {
namespace core {

// What the search reads: the classes of the last pass, the nearest-reliable
// map (index or -1), the depths of the reference image and the depth edges of
// the segmentation prior (same size; edges.data == nullptr = unconfined, as
// in APD-MVS and the ablation "w/o Mul."). `nearest_edge`, when given, maps
// every pixel to its nearest edge pixel (-1: none): walks that cannot reach
// an edge are then not taken.
struct AnchorMaps {
  const uint8_t* classes;
  const int* nearest;
  const float* depth;
  int width;
  int height;
  BoundaryView edges;
  const int* nearest_edge = nullptr;
};

MSP_HD bool IsConfined(const AnchorMaps& maps) { return maps.edges.data != nullptr; }

// True when no edge pixel can lie on the walk from (c0, r0) to (c1, r1), both
// in the image: every pixel of a Bresenham walk lies within half a pixel of
// the segment, so within its length + 0.5 of the start (a pixel of margin
// here, for rounding), and its bounding box keeps it in the image.
MSP_HD bool OutOfEdgeReach(const AnchorMaps& maps, int c0, int r0, int c1, int r1) {
  if (maps.nearest_edge == nullptr) return false;
  const int e = maps.nearest_edge[r0 * maps.width + c0];
  if (e < 0) return true;
  const float ex = static_cast<float>(e % maps.width - c0);
  const float ey = static_cast<float>(e / maps.width - r0);
  const float lx = static_cast<float>(c1 - c0), ly = static_cast<float>(r1 - r0);
  const float reach = sqrtf(lx * lx + ly * ly) + 1.0f;
  return ex * ex + ey * ey > reach * reach;
}

// SegmentCrossesBoundary on the edges of `maps`, skipped when out of reach.
MSP_HD bool WalkCrossesEdge(const AnchorMaps& maps, int c0, int r0, int c1, int r1) {
  return !OutOfEdgeReach(maps, c0, r0, c1, r1) &&
         SegmentCrossesBoundary(maps.edges, c0, r0, c1, r1);
}

// Paper "Edge Aggregation": the anchor s is admissible for p only if the
// line p -> s crosses no edge of B'.
MSP_HD bool CrossesDepthEdge(const AnchorMaps& maps, int col, int row, int q) {
  return IsConfined(maps) && WalkCrossesEdge(maps, col, row, q % maps.width, q / maps.width);
}

}  // namespace core
}  // namespace msp

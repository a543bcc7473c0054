// Capacities of the segmentation prior (docs/method.md section 4), defined once: option checks, the
// mask reader and the per-pixel arrays all use these.
#pragma once

#include <cstdint>

namespace msp {
namespace core {

// Label layers per image. A pixel's set of best layers (eq. 4, ties kept) is a
// uint32_t bit set, so this many layers fit; the paper uses 3.
constexpr int kMaxLabelLayers = 32;
// Geometry label layers (segmented depth and normal maps) added to the
// embedded colour layers with --MspStereo.geometry_layers: one granularity.
// On exact depth and normal maps of the bundled scene k = 300 and k = 1000
// give the same segments, while k = 100 cuts slanted surfaces apart (99 %
// against 38-65 % of the segment edges on depth edges or creases,
// msp_bench_segmenters), so a second, finer layer could only add false edges.
constexpr int kNumGeometryLayers = 1;
// Anchors of one unreliable pixel seen by the prior: 8 sectors x 4 anchors of
// the disassemble-clustering step; a pixel's anchor subset S_n is a uint32_t
// bit set over them.
constexpr int kMaxPriorAnchors = 32;

static_assert(kMaxLabelLayers <= 32, "best-layer sets are uint32_t bit sets");
static_assert(kNumGeometryLayers < kMaxLabelLayers, "geometry layers leave room for colour");
static_assert(kMaxPriorAnchors <= 32, "anchor subsets are uint32_t bit sets");

}  // namespace core
}  // namespace msp

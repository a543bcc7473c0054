// Capacities and labels of the deformable patch matching of the APD-MVS
// baseline (docs/method.md section 3), defined once: the per-pixel arrays, the
// option checks and the whole-image steps all use these.
#pragma once

#include <cstdint>

namespace msp {
namespace core {

// Pixel classes after a pass (docs/method.md section 3.1). Unknown pixels (border, no
// depth, no selected view, or no anchors) use conventional PatchMatch.
constexpr uint8_t kUnknown = 0;
constexpr uint8_t kReliable = 1;
constexpr uint8_t kUnreliable = 2;

// The reliability curve samples disparity offsets -30..30 px around the depth.
constexpr int kCurveHalfWidth = 30;
constexpr int kCurveSamples = 2 * kCurveHalfWidth + 1;

// Anchor search: 8 sectors of 45 degrees, up to 4 rays per sector at the
// finest rounds (2 at the coarsest).
constexpr int kNumSectors = 8;
constexpr int kMaxRaysPerSector = 4;
constexpr int kMaxAnchorHits = kNumSectors * kMaxRaysPerSector;
// The deformable patch uses the 8 inliers closest to the RANSAC plane: one
// vector lane each. With disassemble-clustering every inlier is kept (up to
// one per ray hit) and the lanes are anchor clusters, at most kMaxAnchors.
constexpr int kMaxAnchors = 8;
constexpr int kMaxKeptAnchors = kMaxAnchorHits;

static_assert(kMaxAnchors <= kMaxAnchorHits, "anchors are chosen among the ray hits");

}  // namespace core
}  // namespace msp

// Host storage of one image's per-pixel PatchMatch state: the plane (depth +
// normal), the aggregated cost and the selected-view mask, 24 bytes per
// pixel, plus the segmentation prior's edge map (1 byte per pixel) once the
// prior has run for the image, the reliability classes (1 byte per pixel)
// between the passes of a deformable round, in a geometric pass the depth
// the pass started from (4 bytes per pixel) and the colour segments of
// segment planes (4 bytes per pixel).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"

namespace msp {

struct PixelState {
  int width = 0;
  int height = 0;
  std::vector<float> depth;   // camera z, 0 = none
  std::vector<float> normal;  // 3 planes: nx, ny, nz
  std::vector<float> cost;
  std::vector<uint32_t> mask;
  // Depth edges of the segmentation prior (bits of prior/prior_driver.h); empty
  // until the prior first runs. Kept here so it spills and upsamples with
  // the planes it belongs to.
  std::vector<uint8_t> edges;
  // Reliability classes (core::kReliable ...) of these planes, computed at
  // the end of a pass for the next pass of the round; empty otherwise.
  std::vector<uint8_t> classes;
  // The colour segments of segment planes at this round's size
  // (SegmentPlaneLabels), made by the round's first pass that needs them;
  // empty before, and after a spill (not saved: made again).
  std::vector<int32_t> segments;
  // The open-sky pixels (open_sky.h) the round's last segment-plane step
  // found, which the next passes leave without a plane; empty when none, and
  // made again with the segments.
  std::vector<uint8_t> open_sky;
  // In a geometric pass, once it has updated this image: the depth before,
  // which the pass's later images read (passes are Jacobi); else empty.
  std::vector<float> previous_depth;

  PixelState() = default;
  PixelState(int w, int h)
      : width(w),
        height(h),
        depth(static_cast<size_t>(w) * h, 0.0f),
        normal(static_cast<size_t>(w) * h * 3, 0.0f),
        cost(static_cast<size_t>(w) * h, core::kMaxCost),
        mask(static_cast<size_t>(w) * h, 0u) {}

  bool Empty() const { return depth.empty(); }
  size_t Bytes() const {
    return depth.size() * sizeof(float) + normal.size() * sizeof(float) +
           cost.size() * sizeof(float) + mask.size() * sizeof(uint32_t) + edges.size() +
           classes.size() + previous_depth.size() * sizeof(float) +
           segments.size() * sizeof(int32_t);
  }
  core::PlaneHypothesis Plane(size_t i) const {
    const size_t n = depth.size();
    return core::PlaneHypothesis{depth[i], core::Vec3{normal[i], normal[n + i], normal[2 * n + i]}};
  }
  core::PixelStateView View() {
    return core::PixelStateView{depth.data(), normal.data(), cost.data(),
                                mask.data(),  width,         height};
  }
};

}  // namespace msp

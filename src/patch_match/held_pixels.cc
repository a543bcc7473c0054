#include "patch_match/held_pixels.h"

#include <algorithm>
#include <cmath>

#include "base/parallel_for.h"
#include "core/math/plane.h"
#include "core/patch_match/window_texture.h"

namespace msp {
namespace {

// A neighbour continues the pixel's plane when its depth is within this
// share of the plane's depth there.
constexpr float kPlaneDepthTolerance = 0.01f;

// Whether the pixels a window's radius away in the 8 directions, where they
// have a plane, lie on the plane of pixel (col, row).
bool OnItsNeighboursPlane(const core::PassParams& params, int col, int row) {
  const core::PixelStateView& s = params.state;
  const core::PlaneHypothesis h = s.Get(s.Index(col, row));
  if (!(h.depth > 0.0f)) return false;
  const int r = params.ncc.window_radius;
  for (int dy = -r; dy <= r; dy += r) {
    for (int dx = -r; dx <= r; dx += r) {
      const int c = col + dx, y = row + dy;
      if ((dx == 0 && dy == 0) || c < 0 || y < 0 || c >= s.width || y >= s.height) continue;
      const float depth = s.depth[s.Index(c, y)];
      if (!(depth > 0.0f)) continue;
      const float on_plane = core::PropagatedDepth(params.ref_camera, col, row, h, c, y);
      if (!(std::fabs(depth - on_plane) <= kPlaneDepthTolerance * on_plane)) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<uint8_t> HeldPixels(const core::PassParams& params, int num_threads) {
  const int width = params.state.width;
  std::vector<uint8_t> held(static_cast<size_t>(width) * params.state.height, 0);
  ParallelFor(0, params.state.height, num_threads, [&](int row) {
    for (int col = 0; col < width; ++col) {
      held[static_cast<size_t>(row) * width + col] =
          core::IsWeaklyTextured(params, col, row) && OnItsNeighboursPlane(params, col, row) ? 1
                                                                                             : 0;
    }
  });
  if (std::find(held.begin(), held.end(), 1) == held.end()) return {};
  return held;
}

}  // namespace msp

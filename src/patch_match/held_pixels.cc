#include "patch_match/held_pixels.h"

#include <algorithm>

#include "base/parallel_for.h"
#include "core/patch_match/window_texture.h"

namespace msp {

std::vector<uint8_t> WeaklyTexturedPixels(const core::PassParams& params, int num_threads) {
  const int width = params.state.width;
  std::vector<uint8_t> weak(static_cast<size_t>(width) * params.state.height, 0);
  ParallelFor(0, params.state.height, num_threads, [&](int row) {
    for (int col = 0; col < width; ++col) {
      weak[static_cast<size_t>(row) * width + col] =
          core::IsWeaklyTextured(params, col, row) ? 1 : 0;
    }
  });
  if (std::find(weak.begin(), weak.end(), 1) == weak.end()) return {};
  return weak;
}

}  // namespace msp

// Compiles every src/core header for the device, so host/device compatibility
// of the shared per-pixel code is checked on every build with nvcc. The kernel
// runs the conventional PatchMatch update for one colour of a checkerboard:
// the same function the CPU driver calls.
#include "core/camera.h"
#include "core/checkerboard.h"
#include "core/geometric_cost.h"
#include "core/hd.h"
#include "core/homography.h"
#include "core/image_view.h"
#include "core/limits.h"
#include "core/local_refine.h"
#include "core/ncc.h"
#include "core/output_filter.h"
#include "core/patch_match_kernel.h"
#include "core/plane.h"
#include "core/rng.h"
#include "core/vec.h"
#include "core/view_selection.h"
#include "cuda/core_check.h"

namespace msp {
namespace cuda {
namespace {

// Threads per block of the 2D launch: 16 x 16 covers a tile of pixels.
constexpr int kBlockSide = 16;

__global__ void CheckerboardKernel(const core::PassParams* params, int color, int iteration) {
  const int col = blockIdx.x * blockDim.x + threadIdx.x;
  const int row = blockIdx.y * blockDim.y + threadIdx.y;
  if (col >= params->state.width || row >= params->state.height) return;
  if (((col + row) & 1) != color) return;
  core::UpdatePixel(*params, col, row, iteration);
}

}  // namespace

void LaunchCheckerboard(const core::PassParams* device_params, int width, int height, int color,
                        int iteration) {
  const dim3 block(kBlockSide, kBlockSide);
  const dim3 grid((width + kBlockSide - 1) / kBlockSide, (height + kBlockSide - 1) / kBlockSide);
  CheckerboardKernel<<<grid, block>>>(device_params, color, iteration);
}

}  // namespace cuda
}  // namespace msp

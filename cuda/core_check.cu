// Compiles every src/core header for the device, so host/device compatibility
// of the shared per-pixel code is checked on every build with nvcc. Its
// kernels (a deformable checkerboard colour, the classification) call the
// same functions as the CPU driver; the sweeps the CUDA back-end runs are in
// sweep_kernels.cu.
#include "core/cost/ncc.h"
#include "core/cost/ref_window.h"
#include "core/cost/window_batch.h"
#include "core/cost/window_cost.h"
#include "core/deformable/anchor_windows.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/deformable_limits.h"
#include "core/deformable/deformable_update.h"
#include "core/deformable/refine_and_classify.h"
#include "core/deformable/reliability.h"
#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/limits.h"
#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/math/vec.h"
#include "core/math/warped_sample.h"
#include "core/patch_match/checkerboard.h"
#include "core/patch_match/geometric_cost.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/output_filter.h"
#include "core/patch_match/patch_match_kernel.h"
#include "core/patch_match/view_selection.h"
#include "core/prior/best_layer.h"
#include "core/prior/prior_limits.h"
#include "core/prior/segment_crossing.h"
#include "cuda/core_check.h"
#include "cuda/launch_geometry.cuh"

namespace msp {
namespace cuda {
namespace {

// Deformable iteration of one colour: unreliable pixels with anchors take the
// deformable update (APD), the others the conventional one.
__global__ void DeformableKernel(const core::PassParams* params, const core::AnchorMaps* maps,
                                 const core::AnchorParams* anchor_params, core::PlaneMapView planes,
                                 core::DeformableParams cost, int color, int iteration) {
  const int col = blockIdx.x * blockDim.x + threadIdx.x;
  const int row = blockIdx.y * blockDim.y + threadIdx.y;
  if (col >= params->state.width || row >= params->state.height) return;
  if (((col + row) & 1) != color) return;
  const int i = row * params->state.width + col;
  core::AnchorSet anchors;
  anchors.count = 0;
  if (maps->classes[i] == core::kUnreliable) {
    core::Rng rng = core::MakeRng(core::RngKey(params->seed, params->image_id, params->pass_id,
                                               iteration, static_cast<uint32_t>(i)));
    core::FindAnchors(params->ref_camera, *maps, col, row, *anchor_params, &rng, &anchors);
  }
  if (anchors.count > 0) {
    core::DeformableUpdatePixel(*params, col, row, iteration, anchors, planes, cost);
  } else {
    core::UpdatePixel(*params, col, row, iteration);
  }
}

__global__ void ClassifyKernel(const core::PassParams* params, core::ReliabilityParams rp,
                               uint8_t* classes) {
  const int col = blockIdx.x * blockDim.x + threadIdx.x;
  const int row = blockIdx.y * blockDim.y + threadIdx.y;
  if (col >= params->state.width || row >= params->state.height) return;
  classes[row * params->state.width + col] = core::ClassifyPixel(*params, col, row, rp);
}

}  // namespace

void LaunchDeformable(const core::PassParams* device_params, const core::AnchorMaps* device_maps,
                      const core::AnchorParams* device_anchor_params,
                      const core::PlaneMapView& planes, const core::DeformableParams& cost,
                      int width, int height, int color, int iteration) {
  DeformableKernel<<<PixelGrid(width, height), PixelBlock()>>>(
      device_params, device_maps, device_anchor_params, planes, cost, color, iteration);
}

void LaunchClassify(const core::PassParams* device_params, const core::ReliabilityParams& rp,
                    uint8_t* device_classes, int width, int height) {
  ClassifyKernel<<<PixelGrid(width, height), PixelBlock()>>>(device_params, rp, device_classes);
}

}  // namespace cuda
}  // namespace msp

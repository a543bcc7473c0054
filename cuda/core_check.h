// Plain C++ launchers of core_check.cu's kernels (no CUDA types here).
#pragma once

#include <cstdint>

#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/deformable_update.h"
#include "core/deformable/reliability.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace cuda {

// One colour of a deformable iteration (DeformableUpdatePixel where the
// pixel is unreliable and has anchors). `device_params` and every pointer
// inside it must be device memory.
void LaunchDeformable(const core::PassParams* device_params, const core::AnchorMaps* device_maps,
                      const core::AnchorParams* device_anchor_params,
                      const core::PlaneMapView& planes, const core::DeformableParams& cost,
                      int width, int height, int color, int iteration);

// Reliability class of every pixel (ClassifyPixel) into device_classes.
void LaunchClassify(const core::PassParams* device_params, const core::ReliabilityParams& rp,
                    uint8_t* device_classes, int width, int height);

}  // namespace cuda
}  // namespace msp

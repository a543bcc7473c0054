// Plain C++ launchers of the deformable step's per-pixel kernels (no CUDA
// types here). Each kernel is one thread per pixel calling the src/core
// function the CPU's row loops call for that pixel
// (src/deformable/deformable_sweeps.cc, core/deformable/deformable_sweep_pixel.h).
// `device_params` and every pointer below must be device memory of the
// current device. Every launcher checks the launch and waits for the kernel.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/deformable/anchor_maps.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/deformable/deformable_update.h"
#include "core/deformable/reliability.h"
#include "core/deformable/synergistic_optimization.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace cuda {

// The rows [row_begin, row_end) of the reference image whose anchor slots
// are on the device, and what the deformable kernels read besides the pass.
// Slots (AssignAnchorSlots) are numbered in pixel order, so the band's are
// slot_begin, slot_begin + 1, ...; hits, anchors and solutions hold only
// those. Everything else is whole-image.
struct DeformableBand {
  int row_begin;
  int row_end;
  int slot_begin;
  const int* slot;            // every pixel's slot, -1 = none
  core::AnchorMaps maps;      // classes, nearest reliable, the snapshot's depth, edges
  core::PlaneMapView planes;  // the iteration's snapshot of the planes
  core::AnchorParams anchor_params;
  core::DeformableParams cost;
  core::AnchorHits* hits;
  core::AnchorSet* anchors;
  uint32_t* solutions;  // sampling solutions; null without the synergistic optimization
  bool optimize;        // the 3D optimization runs in this iteration
  core::SynergyParams synergy;
};

// ClassifyPixel for every pixel, into device_classes.
void LaunchClassify(const core::PassParams* device_params, const core::ReliabilityParams& rp,
                    uint8_t* device_classes, int width, int height);

// FindPixelAnchors for every slotted pixel of the band; adds the number
// that found anchors to *device_anchored.
void LaunchFindAnchors(const core::PassParams* device_params, const DeformableBand& band, int width,
                       int iteration, unsigned long long* device_anchored);

// DeformableSweepPixel for every pixel of `color` (0 red, 1 black) in the
// band, with the anchor sums the CPU takes for these settings
// (core::SharesAnchorPairs: own-plane pairs, else direct).
void LaunchDeformableSweep(const core::PassParams* device_params, const DeformableBand& band,
                           int width, int color, int iteration, bool shares_pairs);

// The largest local memory (stack) per thread of these kernels on the
// current device.
size_t MaxDeformableKernelLocalBytes();

}  // namespace cuda
}  // namespace msp

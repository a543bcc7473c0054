// Open sky (docs/method.md section 2.11): segments that nothing in the images
// says are a surface. Bright, untextured and open to the image border, with
// no plane mostly their own after the segment planes' support rule: the sky above
// a roofline or through a window, a white-out background. Every view sees the
// same smooth brightness there whatever depth it is given, so planes
// propagated from the surface around agree across the views and pass the
// geometric checks; only the absence of evidence tells. The passes leave
// these pixels their planes (they carry the surrounding surface's plane
// across, as the wall around a window), the written maps leave them empty.
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"
#include "core/patch_match/patch_match_kernel.h"
#include "patch_match/segment_planes.h"

namespace msp {

// 1 at the pixels of every segment of `labels` (ids 1..K) that touches the
// image border, is sky-coloured (mean grey of `params.ref_image` and mean
// colour of `color`, the reference image's RGB planes at the pass's level:
// bright and blue, or white-out), is mostly untextured (`texture`:
// core::WindowTextureStd per pixel), and has no plane of its own (`planes`,
// FitSegmentPlanes: none accepted, or one the pixels around its outline
// mostly hold); then the mixed pixels of its outline. Empty when no pixel is.
std::vector<uint8_t> OpenSkyPixels(const core::PassParams& params, const DenseMap& color,
                                   const std::vector<int32_t>& labels,
                                   const std::vector<SegmentPlane>& planes,
                                   const std::vector<float>& texture);

// Depth 0 and normal 0 in `depth` and `normal` (a map's size) where
// `open_sky` is 1; nothing when it is empty.
void ClearOpenSky(const std::vector<uint8_t>& open_sky, DenseMap* depth, DenseMap* normal);

// core::kStageOpenSky in channel 0 of `stages` (ExtractMaps' stages map)
// where `open_sky` is 1 and the pixel had a plane; nothing when it is empty.
void MarkOpenSkyStage(const std::vector<uint8_t>& open_sky, DenseMap* stages);

}  // namespace msp

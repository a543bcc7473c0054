// Open sky (docs/method.md section 2.11): segments that nothing in the images
// says are a surface. Untextured and open to the image border (or joined to
// such a segment), with no evidence of a depth of their own: no matched edge
// but the contours of textured surfaces in front of them, or a plane that
// is only the surrounding surface's carried on. The sky above a roofline or
// through a window, whatever its colour, a blank background. Every view sees the
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

// 1 at the pixels of every segment of `labels` (ids 1..K) that is mostly
// untextured (`window_texture`: core::WindowTextureStd per pixel; a window
// whose content is only an intensity ramp is untextured too,
// ramp_free_texture.h), has no evidence
// of a depth of its own, and touches the image border or a segment that is
// marked: its only matched edges (`params.state`'s pixels on an edge with a
// matching, textured window) are on textured surfaces, or its plane
// (`planes`, FitSegmentPlanes) is one the pixels around its outline mostly
// hold, or it has no accepted plane and a daylight sky's colour (mean grey
// of `params.ref_image`, mean colour of `color`, the reference image's RGB
// planes at the pass's level). Then the mixed pixels of its outline. Empty
// when no pixel is. Runs on up to `num_threads` threads, with the same result.
std::vector<uint8_t> OpenSkyPixels(const core::PassParams& params, const DenseMap& color,
                                   const std::vector<int32_t>& labels,
                                   const std::vector<SegmentPlane>& planes,
                                   const std::vector<float>& window_texture, int num_threads = 1);

// Depth 0 and normal 0 in `depth` and `normal` (a map's size) where
// `open_sky` is 1; nothing when it is empty.
void ClearOpenSky(const std::vector<uint8_t>& open_sky, DenseMap* depth, DenseMap* normal);

// core::kStageOpenSky in channel 0 of `stages` (ExtractMaps' stages map)
// where `open_sky` is 1 and the pixel had a plane; nothing when it is empty.
void MarkOpenSkyStage(const std::vector<uint8_t>& open_sky, DenseMap* stages);

}  // namespace msp

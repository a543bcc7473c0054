// A picture for people of what the segmentation prior did to one image: the
// image, dimmed, with the aggregated edges B' (red), the CRF-refined edges
// (green) and both (yellow) drawn over it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/dense_map.h"

namespace msp {

// <workspace>/stereo/prior_previews/<image_name>.png
std::string PriorPreviewPath(const std::string& workspace_path, const std::string& image_name);

// Writes the preview PNG of `color` (3 planes RGB in [0, 1]) with two
// width x height edge maps (nonzero = edge; either may be empty). Written
// under a temporary name and renamed; throws InputError naming `path`.
void WritePriorPreview(const std::string& path, const DenseMap& color,
                       const std::vector<uint8_t>& aggregated_edges,
                       const std::vector<uint8_t>& refined_edges);

}  // namespace msp

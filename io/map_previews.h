// Pictures of an image's final maps for people (--MspStereo.write_previews):
// its depth on a colour scale, its normals, and where its depth is right or
// wrong against the bundled scene's ground truth. They lie next to the prior
// preview (preview_image.h), so the evaluator can link all of them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "base/dense_map.h"
#include "io/colormaps.h"
#include "io/ground_truth.h"
#include "io/preview_image.h"

namespace msp {

enum class MapPreview { kDepth, kNormal, kError };

// <workspace>/stereo/prior_previews/<image_name>.{depth,normal,error}.png
std::string MapPreviewPath(const std::string& workspace_path, const std::string& image_name,
                           MapPreview preview);

// The 2nd to 98th percentile of the valid depths (finite, > 0), so that a few
// stray depths do not squeeze the colours of every other; {0, 0} when none.
DepthRange RobustDepthRange(const DenseMap& depth);

// `depth` (1 channel) through DepthColor over its RobustDepthRange.
RgbImage DepthPreview(const DenseMap& depth);
// `normal` (3 channels) through NormalColor.
RgbImage NormalPreview(const DenseMap& normal);
// Every pixel of `depth` classed against the ground-truth pixel nearest to it
// (NearestGroundTruthIndex: the ground truth may be larger), at the map's size.
RgbImage ErrorPreview(const DenseMap& depth, const DenseMap& gt_depth, const double thresholds[2],
                      bool zero_is_empty = false);

// Writes the depth and normal previews of `image_name` and, when
// `ground_truth` is given and lists the image, its error preview; each PNG
// atomically. Throws InputError when a file cannot be read or written.
void WriteMapPreviews(const std::string& workspace_path, const std::string& image_name,
                      const DenseMap& depth, const DenseMap& normal,
                      const GroundTruthInfo* ground_truth);

// The previews of `image_name` that exist, as (kind, path) in the order
// depth, normal, error, prior: what the evaluator's report links.
std::vector<std::pair<std::string, std::string>> ExistingPreviews(const std::string& workspace_path,
                                                                  const std::string& image_name);

}  // namespace msp

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

enum class MapPreview { kDepth, kNormal, kError, kStages };

// <workspace>/stereo/prior_previews/<image_name>.{depth,normal,error,stages}.png
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

// The stages map (ExtractMaps: channel 0 a core::MapStage, channel 1 the
// depth before the filter) as colours: kept light grey, no plane black, open
// sky blue, removed by the filter's triangulation angle yellow, its NCC
// magenta, its reprojection error red, by several tests orange.
RgbImage StagesPreview(const DenseMap& stages);

// <workspace>/stereo/prior_previews/<image_name>.stages.bin: the stages map
// itself, in COLMAP's dense-map format, for bench/map_stages.py.
std::string StagesMapPath(const std::string& workspace_path, const std::string& image_name);

// Writes the stages map of `image_name` and its picture, each atomically.
void WriteStagesMap(const std::string& workspace_path, const std::string& image_name,
                    const DenseMap& stages);

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

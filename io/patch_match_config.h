// stereo/patch-match.cfg as COLMAP's PatchMatchController::ReadProblems parses
// it, source-image selection (__all__, __auto__ N, explicit lists) and the
// per-image depth ranges of Model::ComputeDepthRanges.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "base/mvs_input.h"
#include "io/sparse_model.h"

namespace msp {

struct PatchMatchConfigEntry {
  enum class Kind { kAll, kAuto, kList };
  std::string ref_name;
  Kind kind = Kind::kList;
  int num_auto = 0;                    // kAuto: how many sources
  std::vector<std::string> src_names;  // kList
};

// Trimmed lines, '#' comments and empty lines skipped, taken in pairs
// (reference name, source spec split on ',' or ';'). Throws InputError.
std::vector<PatchMatchConfigEntry> ParsePatchMatchConfig(const std::string& path);
std::vector<PatchMatchConfigEntry> ParsePatchMatchConfigText(const std::string& text,
                                                             const std::string& path_for_errors);

// COLMAP's __auto__ ranking: images sharing sparse points with `ref_index`
// whose 75th-percentile triangulation angle is >= min_triangulation_angle_deg,
// sorted by shared point count (descending), at most `num` of them.
std::vector<int> SelectAutoSources(const SparseModel& model, int ref_index, int num,
                                   double min_triangulation_angle_deg);

// SelectAutoSources for every image i with num_per_image[i] > 0 in one pass
// over the points (COLMAP computes all pairs at once too); the result has one
// (possibly empty) list per model image.
std::vector<std::vector<int>> SelectAutoSourcesBatch(const SparseModel& model,
                                                     const std::vector<int>& num_per_image,
                                                     double min_triangulation_angle_deg);

// Depth range of an image from the z of the points in its track observations:
// values at size*0.01 and size*0.99 of the sorted positive depths, times 0.75
// and 1.25. {-1, -1} when the image observes no point in front of it.
std::pair<double, double> ComputeDepthRange(const SparseModel& model, int image_index);
// ComputeDepthRange of every model image, in one pass over the points.
std::vector<std::pair<double, double>> ComputeDepthRanges(const SparseModel& model);

// The same rule over more evidence, per problem: the points observed by its
// reference or by any of its sources that lie in front of the reference and
// project inside its image. Where the reference's own tracks are few (blurred
// or textureless frames), its sources' tracks on the surfaces they share with
// it widen the range to what it sees. {-1, -1} when no such point exists.
// Each problem visits only its views' observations.
std::vector<std::pair<double, double>> ComputeSharedDepthRanges(
    const SparseModel& model, const std::vector<Problem>& problems);

}  // namespace msp

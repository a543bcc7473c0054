// Consensus planes (docs/method.md section 2.13): in a geometric pass, the
// pixels of a region whose depth the other views bring back are points on its
// surfaces; planes fitted to them by sequential RANSAC average the depth noise
// of thousands of confirmed pixels, and the region's weakly textured pixels
// are offered them. The region bounds where a plane may reach. A colour
// segment may join two surfaces of one colour, so its planes go only to the
// pixels within a few percent of them (they sharpen right depth); a region of
// the user's mask layers is one surface, and all its weakly textured pixels
// take the nearest of its planes (they also replace wrong depth).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"
#include "patch_match/segment_planes.h"

namespace msp {

struct ConsensusPlanesReport {
  int num_planes = 0;   // planes fitted over all regions
  int num_offered = 0;  // weakly textured pixels offered a plane
  int num_taken = 0;    // pixels that took it
};

// A plane of confirmed points (camera frame), normal facing the camera.
struct ConsensusPlane {
  core::Vec3 normal;
  core::Vec3 point;
  int num_inliers = 0;  // points within 0.5 % of depth
  int num_claimed = 0;  // points within 2 %, which the next plane does not see
};

// Up to a few planes through `points` (camera frame; `rays` the viewing rays
// of their pixels, z = 1), each the least-squares refit of a RANSAC winner
// over the points the earlier planes left, holding at least `min_inliers`
// points within kInlierDepth of depth along their rays and a fifth of them.
// Deterministic for a given `key`.
std::vector<ConsensusPlane> FitConsensusPlanes(const std::vector<core::Vec3>& points,
                                               const std::vector<core::Vec3>& rays, int min_inliers,
                                               uint64_t key);

// How a region's planes are offered: to each weakly textured pixel of the
// region whose depth lies within `max_depth` (relative) of one of them, which
// takes the nearest unless that costs `margin` more over its selected views
// than its own plane (core::OfferSegmentPlane). With `one_surface`, only in a
// region whose confirmed pixels lie on one plane (kOneSurfaceShare of them
// within 2 %); the other regions get kSegmentOffer.
struct ConsensusOffer {
  float max_depth;
  float margin;
  bool one_surface;
};

// Colour segments join surfaces of one colour: a plane goes only to the
// pixels already on its surface, with noise (with 5 % the bundled scene's
// textureless pixels within 5 % fell by 1.7 points: a wrong plane that the
// views agree on reached further), under the segment planes' margin.
constexpr ConsensusOffer kSegmentOffer{0.03f, kTexturelessMargin, false};
// A region of the user's mask layers is meant to be one surface (what a
// segmenter such as Semantic-SAM is for); where the views confirm that it is
// one plane, every weakly textured pixel of it takes that plane, whatever its
// depth and cost: a pixel's own cost, where the views agree on a wrong depth,
// is no evidence against it (with the margin the bundled scene's ideal masks
// gave a third of the gain). A region of several planes (a mask that joins a
// wall and the floor: with the scene's object-level masks as the finest layer
// and no such check, fused F1 at 0.5 % fell from 68 to 45 %) gets
// kSegmentOffer.
constexpr ConsensusOffer kMaskRegionOffer{std::numeric_limits<float>::infinity(),
                                          core::kUnboundedCost, true};
constexpr double kOneSurfaceShare = 0.8;

// The whole step on the state of `params`: planes of every region of
// `labels` (ids >= 1) over its `evidence` pixels (1), then their offer.
ConsensusPlanesReport OfferConsensusPlanes(const core::PassParams& params,
                                           const std::vector<int32_t>& labels,
                                           const std::vector<uint8_t>& evidence,
                                           const ConsensusOffer& offer, int num_threads);

}  // namespace msp

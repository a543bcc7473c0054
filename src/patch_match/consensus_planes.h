// Consensus planes (docs/method.md section 2.13): in a geometric pass, the
// pixels of a colour segment whose depth the other views bring back are
// points on its surfaces; planes fitted to them by sequential RANSAC average
// the depth noise of thousands of confirmed pixels, and every weakly textured
// pixel of the segment that lies within a few percent of one of them is
// offered it. The segment bounds where a plane may reach; the tolerance keeps
// a plane to the pixels already on its surface, so it sharpens their depth
// without carrying one surface's plane onto another of the same colour.
#pragma once

#include <cstdint>
#include <vector>

#include "core/patch_match/patch_match_kernel.h"

namespace msp {

struct ConsensusPlanesReport {
  int num_planes = 0;   // planes fitted over all segments
  int num_offered = 0;  // weakly textured pixels within the tolerance of a plane
  int num_taken = 0;    // pixels that took it
};

// A plane of confirmed points (camera frame), normal facing the camera.
struct ConsensusPlane {
  core::Vec3 normal;
  core::Vec3 point;
  int num_inliers = 0;
};

// Up to a few planes through `points` (camera frame; `rays` the viewing rays
// of their pixels, z = 1), each the least-squares refit of a RANSAC winner
// over the points the earlier planes left, holding at least `min_inliers`
// points within kInlierDepth of depth along their rays and a fifth of them.
// Deterministic for a given `key`.
std::vector<ConsensusPlane> FitConsensusPlanes(const std::vector<core::Vec3>& points,
                                               const std::vector<core::Vec3>& rays, int min_inliers,
                                               uint64_t key);

// Relative depth within which a weakly textured pixel is offered a colour
// segment's plane: it is on that surface already, with noise. With 5 % the
// bundled scene's textureless pixels within 5 % fell by 1.7 points (a wrong
// plane that the views agree on reached further).
constexpr float kSegmentOfferDepth = 0.03f;

// The whole step on the state of `params`: planes of every region of
// `labels` (ids >= 1) over its `evidence` pixels (1), then the offer of the
// nearest plane to each weakly textured pixel of the region whose depth lies
// within `max_offer_depth` of it (relative; infinity = every such pixel),
// under the segment planes' rule (OfferPlane).
ConsensusPlanesReport OfferConsensusPlanes(const core::PassParams& params,
                                           const std::vector<int32_t>& labels,
                                           const std::vector<uint8_t>& evidence,
                                           float max_offer_depth, int num_threads);

}  // namespace msp

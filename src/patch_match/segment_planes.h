// Segment planes (docs/method.md section 2.10): after a pass, the reference
// image is cut into colour segments; the matched edge pixels on and around
// each segment give its plane by RANSAC in 3D, and every pixel of the
// segment is offered that plane (core/patch_match/segment_plane.h). Textured
// pixels keep their plane unless the segment's matches better; textureless
// ones take it unless the views clearly reject it, so a blank wall gets the
// plane its borders fix instead of whatever a noise-level cost let through.
#pragma once

#include <cstdint>
#include <vector>

#include "base/dense_map.h"
#include "core/math/vec.h"
#include "core/patch_match/patch_match_kernel.h"
#include "prior/graph_segmentation.h"

namespace msp {

// Two planes through a shared point are the same surface when their normals
// are within 10 degrees: cos(10 degrees).
constexpr float kSamePlaneCos = 0.985f;

struct SegmentPlane {
  core::Vec3 normal{};  // unit, camera frame (zero for a segment without a fit)
  core::Vec3 point{};   // a point of the plane, camera frame
  int num_support = 0;  // reliable pixels on or next to the segment
  int num_inliers = 0;
  // Inliers that are the segment's own evidence: not on its border with a
  // neighbour whose plane is the same (FitSegmentPlanes).
  int num_own = 0;
  bool accepted = false;  // enough own inliers, spanning two image directions
};

struct SegmentPlanesReport {
  int num_segments = 0;
  int num_planes = 0;    // segments whose plane passed the checks
  int num_offered = 0;   // pixels in those segments
  int num_taken = 0;     // pixels that took the segment's plane
  int num_open_sky = 0;  // pixels of open-sky segments (their maps are left empty)
};

// The rules of the step, each with its --MspStereo.* switch.
struct SegmentPlaneRules {
  bool own_support = true;  // FitSegmentPlanes' support rule
  bool confirm = false;     // ConfirmSegmentPlanes
  bool open_sky = true;     // OpenSkyPixels (open_sky.h) cleared
};

// Fits the plane of every segment of `labels` (ids 1..K, 0 = none) from the
// pixels of `reliable` (1 = reliable) on it or 4-adjacent to it, RANSAC seeded
// by `key`; segments without a well-supported plane that spans two image
// directions are not accepted. Then the support rule: an inlier on the
// segment's border with a neighbour whose own plane is the same plane is
// borrowed (the edge belongs to the neighbour: a window's outline against the
// sky, a roofline, a silhouette), and a plane is accepted only on its own
// inliers. A crease lies on two different planes and counts for both; a
// segment whose support lies only where a coplanar neighbour ends is that
// neighbour extended across a colour edge, with no evidence of its own.
// Index = segment id. Without `own_support`, every inlier counts. The
// segments are fitted on up to `num_threads` threads, with the same result.
std::vector<SegmentPlane> FitSegmentPlanes(const core::PassParams& params,
                                           const std::vector<int32_t>& labels,
                                           const std::vector<uint8_t>& reliable, uint64_t key,
                                           bool own_support = true, int num_threads = 1);

// The segments of `segments` cut at the edges of `regions` (a label image of
// the same size: the finest mask layer): pixels share a label when they share
// both, ids 1..K in the order of their first pixel, 0 where `segments` is 0.
// A colour segment that joins surfaces of one colour (a wall and the face of
// a pillar before it) so gets one plane per surface the regions tell apart.
// Region 0 (unlabelled) cuts nothing: its pixels stay with their segment's
// largest labelled piece.
std::vector<int32_t> SegmentsWithinRegions(const std::vector<int32_t>& segments,
                                           const std::vector<int32_t>& regions);

// Least-squares plane of `points` (at least 3, camera frame): their centroid
// `point` and the direction of least spread `normal` (unit, either sign).
void LeastSquaresPlane(const std::vector<core::Vec3>& points, core::Vec3* normal,
                       core::Vec3* point);

// A textureless pixel takes its segment's plane unless that costs this much
// more than its own (costs of noise-level windows differ by about this much).
constexpr float kTexturelessMargin = 0.1f;

// Offers pixel (col, row) the plane through `point` with `normal` (camera
// frame) under the segment planes' rule (core::OfferSegmentPlane): the pixel
// takes it unless it costs `margin` more than its own plane. True when the
// pixel took it.
bool OfferPlane(const core::PassParams& params, int col, int row, core::Vec3 normal,
                core::Vec3 point, float margin);
// The segment planes' margin: kTexturelessMargin for a weakly textured
// pixel, 0 for a textured one (it takes only a cheaper plane).
inline float SegmentPlaneMargin(bool weakly_textured) {
  return weakly_textured ? kTexturelessMargin : 0.0f;
}

// The colour segments of segment planes: `color` (the reference image at the
// pass's level, RGB planes) cut by `segmenter`, ids 1..K. The same for every
// pass of a round, so the runner keeps them with the image's state.
std::vector<int32_t> SegmentPlaneLabels(const DenseMap& color, Segmenter segmenter);

// Confirmation by the other views (geometric passes): on every 4th pixel of
// every 4th row of each segment with an accepted plane, the plane and the
// plane the pixel holds are reprojected through each source's depth map
// (core::ComposedReprojectionError); a pixel confirms a plane when some
// source brings it back within 1 px. A plane that fewer than half as many
// sampled pixels confirm as confirm their own planes is no longer accepted:
// the views say the segment's pixels are better where they are. Without source depth maps
// (photometric passes) nothing changes.
void ConfirmSegmentPlanes(const core::PassParams& params, const std::vector<int32_t>& labels,
                          int num_threads, std::vector<SegmentPlane>* planes);

// The whole step on the state of `params`: fits the planes of the segments
// `labels` (SegmentPlaneLabels) under `rules`, offers them, and writes the
// open-sky pixels to `open_sky` (when given; empty when there are none), which
// the pass's maps leave empty.
// `color`: the reference image's RGB planes at the pass's level, which the
// open-sky rule needs (null: the rule does not run).
SegmentPlanesReport ApplySegmentPlanes(const core::PassParams& params,
                                       const std::vector<int32_t>& labels, int num_threads,
                                       const SegmentPlaneRules& rules = SegmentPlaneRules(),
                                       const DenseMap* color = nullptr,
                                       std::vector<uint8_t>* open_sky = nullptr);

}  // namespace msp

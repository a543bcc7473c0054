// Planar prior (docs/method.md section 2.12), after ACMP's: in a geometric
// pass, the pixels whose plane the other views' depth maps bring back are the
// evidence; a Delaunay triangulation of a grid sample of them gives a plane
// per triangle, and every pixel inside a triangle that the views do not
// confirm is offered that plane under the segment planes' rule (weakly
// textured pixels take it unless the views clearly reject it). The
// segmentation bounds where the evidence may reach: a triangle whose corners
// lie in different regions spans two surfaces and gives nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "core/patch_match/output_filter.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {

struct PlanarPriorReport {
  int num_evidence = 0;   // pixels the views confirm
  int num_triangles = 0;  // triangles inside one region
  int num_offered = 0;    // unconfirmed pixels inside them
  int num_taken = 0;      // pixels that took their triangle's plane
};

// A triangle of evidence pixels and the plane through their 3D points
// (camera frame), normal facing the camera.
struct PriorTriangle {
  int corner[3][2];  // (col, row) of the corners
  core::Vec3 normal;
  core::Vec3 point;
};

// The triangles of the Delaunay triangulation of `vertices` ((col, row) pairs
// of pixels with a depth in `params.state`) whose corners share one label of
// `labels` (ids >= 1; 0 = none, never shared; empty = no bound) and whose
// plane is not seen edge-on.
std::vector<PriorTriangle> PriorTriangles(const core::PassParams& params,
                                          const std::vector<int32_t>& labels,
                                          const std::vector<int>& vertices);

// The evidence of a geometric pass: 1 where core::CountAgreeingViews >=
// filter.min_num_consistent (the output filter's geometric test without its
// NCC test).
std::vector<uint8_t> ConfirmedPixels(const core::PassParams& params,
                                     const core::FilterParams& filter, int num_threads);

// The whole step on the state of `params` (nothing outside geometric passes):
// ConfirmedPixels, then OfferPriorPlanes.
PlanarPriorReport ApplyPlanarPrior(const core::PassParams& params, const core::FilterParams& filter,
                                   const std::vector<int32_t>& labels, int num_threads);

// One vertex per grid cell (its pixel of `evidence` (1) with the lowest
// cost), the PriorTriangles bounded by `labels`, and the offer of each
// triangle's plane to the pixels inside it that are not evidence.
PlanarPriorReport OfferPriorPlanes(const core::PassParams& params,
                                   const std::vector<int32_t>& labels,
                                   const std::vector<uint8_t>& evidence, int num_threads);

}  // namespace msp

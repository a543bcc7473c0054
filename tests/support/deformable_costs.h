// One-view and one-hypothesis forms of the deformable cost
// (core/deformable/deformable_cost.h) that the driver does not call: what the
// cost tests compare the driver's forms against, and what the benchmark times.
#pragma once

#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace test {

// Deformable cost of a prepared hypothesis at the centre pixel in source
// view j; the geometric term is added in geometric passes exactly as in
// ViewCosts. `conventional`, when given, receives the conventional cost of
// the same plane in view j (its entry of ViewCosts).
inline float DeformableViewCost(const core::PassParams& p, const core::DeformableWindows& w, int j,
                                const core::PreparedPlane& plane, const core::DeformableParams& d,
                                float* conventional = nullptr) {
  if (!plane.valid) {
    if (conventional != nullptr) *conventional = core::kMaxCost;
    return core::kMaxCost;
  }
  float centre;
  const float photometric = core::DeformablePhotometricCost(p, w, j, plane, d, &centre);
  const float geometric = core::GeometricTerm(p, j, w.centre.col, w.centre.row, plane.depth);
  if (conventional != nullptr) *conventional = centre + geometric;
  return photometric + geometric;
}

// The same for a plane and anchors at (col, row): prepares the windows itself.
inline float DeformableViewCost(const core::PassParams& p, int j, int col, int row,
                                const core::PlaneHypothesis& h, const core::AnchorSet& anchors,
                                const core::DeformableParams& d) {
  core::DeformableWindows w;
  core::PrepareDeformableWindows(p, col, row, anchors, d, &w);
  return DeformableViewCost(p, w, j, core::PreparePlane(p, col, row, h), d);
}

// Deformable costs of h in every view with a non-zero weight (all when
// null), and the conventional costs of the same views; the geometric terms
// first, as in ViewCosts.
inline void DeformableViewCosts(const core::PassParams& p, const core::DeformableWindows& w,
                                const core::PlaneHypothesis& h, const core::DeformableParams& d,
                                const float* weights, float* costs, float* conventional) {
  const core::PreparedPlane plane = core::PreparePlane(p, w.centre.col, w.centre.row, h);
  if (!plane.valid) {
    for (int j = 0; j < p.num_src; ++j) costs[j] = conventional[j] = core::kMaxCost;
    return;
  }
  float geometric[core::kMaxSourceViews];
  core::GeometricTerms(p, w.centre.col, w.centre.row, plane, weights, geometric);
  for (int j = 0; j < p.num_src; ++j) {
    if (core::IsWeighted(weights, j)) {
      float centre;
      costs[j] = core::DeformablePhotometricCost(p, w, j, plane, d, &centre) + geometric[j];
      conventional[j] = centre + geometric[j];
    } else {
      costs[j] = conventional[j] = core::kMaxCost;
    }
  }
}

// core::DeformableCandidateViewCosts with the anchor sums computed on the spot
// (core::DirectAnchorSums).
inline void DeformableCandidateViewCosts(const core::PassParams& p,
                                         const core::DeformableWindows& w,
                                         const core::PlaneHypothesis* h, const bool* has, int num,
                                         const core::DeformableParams& d, float* costs,
                                         float* conventional) {
  core::DeformableCandidateViewCosts(p, w, h, has, num, d, core::DirectAnchorSums{p, d}, costs,
                                     conventional);
}

}  // namespace test
}  // namespace msp

// Deformable matching cost of the APD-MVS baseline (paper eq. 3,
// algorithm.md 2.2): m(p, S) = lambda m(p, W) + (1 - lambda) mean_s m(s, W_s).
// W is the usual window at p; W_s a small window at anchor s. Every window is
// warped with p's plane, so the patch deforms to follow the reliable anchors
// of the same surface while keeping p's hypothesis.
#pragma once

#include "core/anchor_windows.h"
#include "core/anchors.h"
#include "core/hd.h"
#include "core/patch_match_kernel.h"

namespace msp {
namespace core {

// APD: the centre window keeps a quarter of the weight; anchor windows are
// 3x3 samples 5 px apart (radius 5, step 5).
constexpr float kDefaultDeformableLambda = 0.25f;
constexpr int kDefaultAnchorWindowRadius = 5;
constexpr int kDefaultAnchorWindowStep = 5;

struct DeformableParams {
  float lambda;              // weight of the centre window
  int anchor_window_radius;  // W_s: offsets -r, -r + step, ..., r around the anchor
  int anchor_window_step;
};

MSP_HD DeformableParams DefaultDeformableParams() {
  return DeformableParams{kDefaultDeformableLambda, kDefaultAnchorWindowRadius,
                          kDefaultAnchorWindowStep};
}

// NCC parameters of the anchor windows: uniform weights (a bilateral weight
// centred on p's colour would be meaningless at the anchor).
MSP_HD NccParams AnchorNccParams(const NccParams& ncc, const DeformableParams& d) {
  NccParams a = ncc;
  a.window_radius = d.anchor_window_radius;
  a.window_step = d.anchor_window_step;
  a.bilateral = 0;
  return a;
}

// The reference side of p's deformable patch: its own window and one per
// anchor, prepared once per pixel update (ref_window.h).
struct DeformableWindows {
  RefWindow centre;
  AnchorWindows anchors;
};

MSP_HD void PrepareDeformableWindows(const PassParams& p, int col, int row,
                                     const AnchorSet& anchors, const DeformableParams& d,
                                     DeformableWindows* w) {
  PrepareWindow(p, col, row, &w->centre);
  PrepareAnchorWindows(p.ref_image, anchors.cols, anchors.rows, anchors.count,
                       d.anchor_window_radius, d.anchor_window_step, &w->anchors);
}

// The photometric part of the deformable cost in source view j under H
// (p's plane), given the centre window's NCC cost `centre`: the anchor
// windows' costs are added to it.
MSP_HD float DeformableFromCentre(const PassParams& p, const DeformableWindows& w, int j,
                                  const Mat3& H, float centre, const DeformableParams& d) {
  const SourceView& s = p.src[j];
  // A view that does not see p costs kMaxCost, as in every matching cost:
  // anchors it does see do not make it a view of p.
  if (w.anchors.count == 0 ||
      (centre >= kMaxCost && !CentreInSource(H, s.image, w.centre.col, w.centre.row))) {
    return centre;
  }
  // H maps every reference pixel on p's plane: an anchor window is the
  // part of p's (deformed) patch that lies around the anchor.
  const float sum = AnchorCostSum(w.anchors, p.ref_image, s.image, H, AnchorNccParams(p.ncc, d));
  return d.lambda * centre + (1.0f - d.lambda) * (sum / w.anchors.count);
}

// The photometric part of the deformable cost of a valid prepared
// hypothesis at the centre pixel in source view j. `centre` receives the
// centre window's NCC cost, the photometric part of ViewCost, which the
// deformable cost computes on the way.
MSP_HD float DeformablePhotometricCost(const PassParams& p, const DeformableWindows& w, int j,
                                       const PreparedPlane& plane, const DeformableParams& d,
                                       float* centre) {
  const Mat3 H = WarpHomography(p.src[j].rel, plane.warp);
  *centre = WindowNccCost(w.centre, p.ref_image, p.src[j].image, H, p.ncc);
  return DeformableFromCentre(p, w, j, H, *centre, d);
}

// Deformable cost of a prepared hypothesis at the centre pixel in source
// view j; the geometric term is added in geometric passes exactly as in
// ViewCost. `conventional`, when given, receives ViewCost of the same plane.
MSP_HD float DeformableViewCost(const PassParams& p, const DeformableWindows& w, int j,
                                const PreparedPlane& plane, const DeformableParams& d,
                                float* conventional = nullptr) {
  if (!plane.valid) {
    if (conventional != nullptr) *conventional = kMaxCost;
    return kMaxCost;
  }
  float centre;
  const float photometric = DeformablePhotometricCost(p, w, j, plane, d, &centre);
  const float geometric = GeometricTerm(p, j, w.centre.col, w.centre.row, plane.depth);
  if (conventional != nullptr) *conventional = centre + geometric;
  return photometric + geometric;
}

// One-off form for tests: prepares the windows itself.
MSP_HD float DeformableViewCost(const PassParams& p, int j, int col, int row,
                                const PlaneHypothesis& h, const AnchorSet& anchors,
                                const DeformableParams& d) {
  DeformableWindows w;
  PrepareDeformableWindows(p, col, row, anchors, d, &w);
  return DeformableViewCost(p, w, j, PreparePlane(p, col, row, h), d);
}

// Deformable costs of h in every view with a non-zero weight (all when
// null), and the conventional costs of the same views; the geometric terms
// first, as in ViewCosts.
MSP_HD void DeformableViewCosts(const PassParams& p, const DeformableWindows& w,
                                const PlaneHypothesis& h, const DeformableParams& d,
                                const float* weights, float* costs, float* conventional) {
  const PreparedPlane plane = PreparePlane(p, w.centre.col, w.centre.row, h);
  if (!plane.valid) {
    for (int j = 0; j < p.num_src; ++j) costs[j] = conventional[j] = kMaxCost;
    return;
  }
  float geometric[kMaxSourceViews];
  GeometricTerms(p, w.centre.col, w.centre.row, plane, weights, geometric);
  for (int j = 0; j < p.num_src; ++j) {
    if (IsWeighted(weights, j)) {
      float centre;
      costs[j] = DeformablePhotometricCost(p, w, j, plane, d, &centre) + geometric[j];
      conventional[j] = centre + geometric[j];
    } else {
      costs[j] = conventional[j] = kMaxCost;
    }
  }
}

static_assert(kMaxAnchors <= kWindowLanes, "one vector lane per anchor's candidate");

// DeformableViewCosts in every view of up to kWindowLanes hypotheses h[k]
// (rows kMaxSourceViews apart; rows whose `has` is false cost kMaxCost), the
// centre windows of all of them at once per view, as CandidateViewCosts.
MSP_HD void DeformableCandidateViewCosts(const PassParams& p, const DeformableWindows& w,
                                         const PlaneHypothesis* h, const bool* has, int num,
                                         const DeformableParams& d, float* costs,
                                         float* conventional) {
  PreparedPlane planes[kWindowLanes];
  float geometric[kWindowLanes][kMaxSourceViews];
  const uint32_t lanes = PrepareCandidates(p, w.centre, h, has, num, planes, geometric);
  for (int j = 0; j < p.num_src; ++j) {
    Mat3 H[kWindowLanes];
    float centre[kWindowLanes];
    CandidateWindowCosts(p, w.centre, j, planes, lanes, num, H, centre);
    for (int k = 0; k < num; ++k) {
      const int i = k * kMaxSourceViews + j;
      if ((lanes >> k) & 1u) {
        costs[i] = DeformableFromCentre(p, w, j, H[k], centre[k], d) + geometric[k][j];
        conventional[i] = centre[k] + geometric[k][j];
      } else {
        costs[i] = conventional[i] = kMaxCost;
      }
    }
  }
}

}  // namespace core
}  // namespace msp

// Deformable matching cost of the APD-MVS baseline (paper eq. 3,
// docs/method.md section 3.3): m(p, S) = lambda m(p, W) + (1 - lambda) mean_s m(s, W_s).
// W is the usual window at p; W_s a small window at anchor s. Every window is
// warped with p's plane, so the patch deforms to follow the reliable anchors
// of the same surface while keeping p's hypothesis.
#pragma once

#include "core/deformable/anchor_clusters.h"
#include "core/deformable/anchor_windows.h"
#include "core/deformable/anchors.h"
#include "core/math/hd.h"
#include "core/patch_match/patch_match_kernel.h"

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
  // Disassemble-clustering (anchor_clusters.h): the lanes are DBSCAN clusters
  // of every kept anchor; false = APD's eight anchor windows.
  bool disassemble_clustering = false;
  ClusterParams clusters = DefaultClusterParams();
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

// The anchor clusters of pixel (col, row) as the lanes of its patch: DBSCAN
// clusters with disassemble-clustering, else every anchor on its own.
MSP_HD void PatchClusters(const AnchorSet& anchors, int col, int row, const DeformableParams& d,
                          AnchorClusters* clusters) {
  if (d.disassemble_clustering) {
    ClusterAnchors(anchors, col, row, d.clusters, clusters);
  } else {
    SingletonClusters(anchors, clusters);
  }
}

// The windows on the fixed sampling grid: APD's anchor windows, or with
// disassemble-clustering the clusters' sub-patches (GridClusterSamples).
MSP_HD void PrepareDeformableWindows(const PassParams& p, int col, int row,
                                     const AnchorSet& anchors, const DeformableParams& d,
                                     DeformableWindows* w) {
  PrepareWindow(p, col, row, &w->centre);
  if (!d.disassemble_clustering) {
    PrepareAnchorWindows(p.ref_image, anchors.cols, anchors.rows, anchors.count,
                         d.anchor_window_radius, d.anchor_window_step, &w->anchors);
    return;
  }
  AnchorClusters clusters;
  ClusterAnchors(anchors, col, row, d.clusters, &clusters);
  LaneSamples samples;
  GridClusterSamples(anchors, clusters, d.anchor_window_radius, p.ref_image.width,
                     p.ref_image.height, &samples);
  PrepareAnchorWindows(p.ref_image, samples, d.anchor_window_radius, &w->anchors);
}

// The photometric part of the deformable cost from the centre window's NCC
// cost and the sum of the anchor windows' costs.
MSP_HD float MixDeformable(float centre, float anchor_sum, int num_anchors,
                           const DeformableParams& d) {
  return d.lambda * centre + (1.0f - d.lambda) * (anchor_sum / num_anchors);
}

// True when the deformable cost in source view j under H adds the anchor
// windows to the centre window's cost `centre`. A view that does not see p
// costs kMaxCost, as in every matching cost: anchors it does see do not make
// it a view of p.
MSP_HD bool AnchorsTakePart(const PassParams& p, const DeformableWindows& w, int j, const Mat3& H,
                            float centre) {
  return w.anchors.count > 0 &&
         !(centre >= kMaxCost && !CentreInSource(H, p.src[j].image, w.centre.col, w.centre.row));
}

// The photometric part of the deformable cost in source view j under H
// (p's plane), given the centre window's NCC cost `centre`: the anchor
// windows' costs are added to it.
MSP_HD float DeformableFromCentre(const PassParams& p, const DeformableWindows& w, int j,
                                  const Mat3& H, float centre, const DeformableParams& d) {
  if (!AnchorsTakePart(p, w, j, H, centre)) return centre;
  // H maps every reference pixel on p's plane: an anchor window is the
  // part of p's (deformed) patch that lies around the anchor.
  const float sum =
      AnchorCostSum(w.anchors, p.ref_image, p.src[j].image, H, AnchorNccParams(p.ncc, d));
  return MixDeformable(centre, sum, w.anchors.count, d);
}

// The photometric part of the deformable cost of a valid prepared
// hypothesis at the centre pixel in source view j. `centre` receives the
// centre window's NCC cost, the conventional PhotometricViewCost, which the
// deformable cost computes on the way.
MSP_HD float DeformablePhotometricCost(const PassParams& p, const DeformableWindows& w, int j,
                                       const PreparedPlane& plane, const DeformableParams& d,
                                       float* centre) {
  const Mat3 H = WarpHomography(p.src[j].rel, plane.warp);
  *centre = WindowNccCost(w.centre, p.ref_image, p.src[j].image, H, p.ncc);
  return DeformableFromCentre(p, w, j, H, *centre, d);
}

// The deformable cost of a view, for BoundedAggregateCost; sums the
// conventional costs of the views it scores on the way.
struct DeformableViewCostSum {
  const PassParams& p;
  const DeformableWindows& w;
  const DeformableParams& d;
  float conventional_sum;  // of weight x (centre window's cost + geometric term)
  int scored;
  MSP_HD float operator()(int j, const PreparedPlane& plane, float weight, float geometric) {
    float centre;
    const float photometric = DeformablePhotometricCost(p, w, j, plane, d, &centre);
    conventional_sum += weight * (centre + geometric);
    ++scored;
    return photometric;
  }
};

// AggregateCost of h's deformable costs in the weighted views
// (DeformablePhotometricCost plus the geometric term, as in ViewCosts), or a
// bound of it at or above `limit` (BoundedAggregateCost; the deformable
// photometric costs are >= 0 as well). With the exact cost, *conventional
// receives the AggregateCost of the conventional costs; it is meaningless
// otherwise.
MSP_HD float DeformableAggregateBelow(const PassParams& p, const DeformableWindows& w,
                                      const PlaneHypothesis& h, const DeformableParams& d,
                                      const float* weights, float limit, float* conventional) {
  DeformableViewCostSum views{p, w, d, 0.0f, 0};
  const float cost = BoundedAggregateCost(p, w.centre.col, w.centre.row, h, weights, limit, views);
  // No view scored: the plane was seen edge-on, or the bound stopped it at once.
  *conventional =
      views.scored > 0 ? views.conventional_sum / TotalWeight(weights, p.num_src) : kMaxCost;
  return cost;
}

static_assert(kMaxAnchors <= kWindowLanes, "one vector lane per anchor's candidate");
static_assert(kMaxSourceViews <= 32, "a view mask has one bit per source view");

// The anchor windows' summed costs of the anchors' candidates: sum[k][j] for
// candidate k in source view j.
struct CandidateAnchorSums {
  float sum[kMaxAnchors][kMaxSourceViews];
};

// Fills the anchor sums of DeformableCandidateViewCosts on the spot, under
// each candidate's plane as prepared at the pixel. Other providers (the CPU
// back-end's cache of shared pairs) must give the same sums up to rounding.
struct DirectAnchorSums {
  const PassParams& p;
  DeformableParams d;
  // Sets out->sum[k][j] for every bit j of need[k].
  MSP_HD void operator()(const AnchorWindows& w, const PreparedPlane* planes, const uint32_t* need,
                         CandidateAnchorSums* out) const {
    for (int k = 0; k < kMaxAnchors; ++k) ForCandidate(w, planes[k], need[k], out->sum[k]);
  }

  // Sets sum[j] for every bit j of `views`: the candidate `plane`'s.
  MSP_HD void ForCandidate(const AnchorWindows& w, const PreparedPlane& plane, uint32_t views,
                           float* sum) const {
    const NccParams anchor_ncc = AnchorNccParams(p.ncc, d);
    for (int j = 0; j < p.num_src; ++j) {
      if (!((views >> j) & 1u)) continue;
      const Mat3 H = WarpHomography(p.src[j].rel, plane.warp);
      sum[j] = AnchorCostSum(w, p.ref_image, p.src[j].image, H, anchor_ncc);
    }
  }
};

// The deformable costs (DeformablePhotometricCost plus the geometric term)
// and the conventional costs in every view of up to kWindowLanes hypotheses
// h[k] (rows kMaxSourceViews apart; rows whose `has` is false cost
// kMaxCost), the centre windows of all of them at once per view, as
// CandidateViewCosts. The anchor windows' sums come from `anchor_sums`
// (DirectAnchorSums' form), asked once for every candidate and view that
// needs them.
template <typename AnchorSumsFn>
MSP_HD void DeformableCandidateViewCosts(const PassParams& p, const DeformableWindows& w,
                                         const PlaneHypothesis* h, const bool* has, int num,
                                         const DeformableParams& d, const AnchorSumsFn& anchor_sums,
                                         float* costs, float* conventional) {
  PreparedPlane planes[kWindowLanes] = {};  // the provider reads the valid ones
  float geometric[kWindowLanes][kMaxSourceViews];
  const uint32_t lanes = PrepareCandidates(p, w.centre, h, has, num, planes, geometric);
  float centre[kMaxAnchors][kMaxSourceViews];
  uint32_t need[kMaxAnchors] = {};
  for (int j = 0; j < p.num_src; ++j) {
    Mat3 H[kWindowLanes];
    float view_centre[kWindowLanes];
    CandidateWindowCosts(p, w.centre, j, planes, lanes, num, H, view_centre);
    for (int k = 0; k < num; ++k) {
      centre[k][j] = view_centre[k];
      if (((lanes >> k) & 1u) && AnchorsTakePart(p, w, j, H[k], view_centre[k])) {
        need[k] |= 1u << j;
      }
    }
  }
  CandidateAnchorSums sums;
  anchor_sums(w.anchors, planes, need, &sums);
  for (int k = 0; k < num; ++k) {
    for (int j = 0; j < p.num_src; ++j) {
      const int i = k * kMaxSourceViews + j;
      if (!((lanes >> k) & 1u)) {
        costs[i] = conventional[i] = kMaxCost;
        continue;
      }
      const float photometric =
          ((need[k] >> j) & 1u) ? MixDeformable(centre[k][j], sums.sum[k][j], w.anchors.count, d)
                                : centre[k][j];
      costs[i] = photometric + geometric[k][j];
      conventional[i] = centre[k][j] + geometric[k][j];
    }
  }
}

}  // namespace core
}  // namespace msp

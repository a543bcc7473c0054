// Deformable matching cost of the APD-MVS baseline (paper eq. 3,
// algorithm.md 2.2): m(p, S) = lambda m(p, W) + (1 - lambda) mean_s m(s, W_s).
// W is the usual window at p; W_s a small window at anchor s. Every window is
// warped with p's plane, so the patch deforms to follow the reliable anchors
// of the same surface while keeping p's hypothesis.
#pragma once

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

// Deformable cost of hypothesis h at (col, row) in source view j; the
// geometric term is added in geometric passes exactly as in ViewCost.
MSP_HD float DeformableViewCost(const PassParams& p, int j, int col, int row,
                                const PlaneHypothesis& h, const AnchorSet& anchors,
                                const DeformableParams& d) {
  const SourceView& s = p.src[j];
  const float dist = PlaneDistance(p.ref_camera, col, row, h);
  if (!(dist > 0.0f)) return kMaxCost;
  const Mat3 H = ComputeHomography(p.ref_camera, s.camera, s.rel, h.normal, dist);
  float cost = NccCost(p.ref_image, s.image, H, col, row, p.ncc);
  if (anchors.count > 0) {
    const NccParams anchor_ncc = AnchorNccParams(p.ncc, d);
    float sum = 0.0f;
    for (int k = 0; k < anchors.count; ++k) {
      // H maps every reference pixel on p's plane: the anchor window is the
      // part of p's (deformed) patch that lies around s.
      sum += NccCost(p.ref_image, s.image, H, anchors.cols[k], anchors.rows[k], anchor_ncc);
    }
    cost = d.lambda * cost + (1.0f - d.lambda) * (sum / anchors.count);
  }
  if (p.geometric && s.depth.data != nullptr) {
    cost += p.geom_lambda *
            ReprojectionError(p.ref_camera, s.camera, s.depth, col, row, h.depth, p.geom_max_error);
  }
  return cost;
}

// Deformable costs of h in every view with a non-zero weight (all when null).
MSP_HD void DeformableViewCosts(const PassParams& p, int col, int row, const PlaneHypothesis& h,
                                const AnchorSet& anchors, const DeformableParams& d,
                                const float* weights, float* costs) {
  for (int j = 0; j < p.num_src; ++j) {
    costs[j] = (weights == nullptr || weights[j] > 0.0f)
                   ? DeformableViewCost(p, j, col, row, h, anchors, d)
                   : kMaxCost;
  }
}

}  // namespace core
}  // namespace msp

// Reliable / unreliable pixels of the APD-MVS baseline (docs/method.md section 3.1):
// with the normal fixed, the view-weighted cost is sampled at 61 disparity
// offsets around the pixel's depth. A single, low, centred minimum makes the
// pixel reliable; a flat or ambiguous curve makes it unreliable, and it will
// be matched with a deformable patch over reliable anchors in the next pass.
#pragma once

#include <cstdint>

#include "core/deformable/deformable_limits.h"
#include "core/math/hd.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Allowed distance of the lowest minimum from the centre, in disparity pixels,
// per pass of a round (APD): 6 after the photometric pass, then 4, 2, 2.
constexpr int kReliabilityRadii[] = {6, 4, 2, 2};
constexpr int kNumReliabilityRadii = sizeof(kReliabilityRadii) / sizeof(kReliabilityRadii[0]);
// APD's cost thresholds (1 - NCC).
constexpr float kDefaultMaxMinimumCost = 0.5f;
constexpr float kDefaultSingleMinimumCost = 0.15f;
constexpr float kDefaultMinMinimumSpread = 0.2f;
// Longest lazily sampled sweep: the curve plus the local refinement's steps
// on either side (refine_and_classify.h).
constexpr int kMaxSweepSamples = kCurveSamples + 2 * kLocalRefineRadius;

struct ReliabilityParams {
  int radius;              // |lowest minimum - centre| allowed, in curve samples
  float max_minimum_cost;  // the lowest minimum must cost at most this
  float single_min_cost;   // with a single minimum: reliable iff its cost <= this
  float min_spread;        // with several: every other minimum must lie this far above
};

MSP_HD int ReliabilityRadius(int pass_index) {
  const int k = pass_index < 0
                    ? 0
                    : (pass_index >= kNumReliabilityRadii ? kNumReliabilityRadii - 1 : pass_index);
  return kReliabilityRadii[k];
}

MSP_HD ReliabilityParams DefaultReliabilityParams(int pass_index) {
  return ReliabilityParams{ReliabilityRadius(pass_index), kDefaultMaxMinimumCost,
                           kDefaultSingleMinimumCost, kDefaultMinMinimumSpread};
}

// True when curve[i] is a strict local minimum; an end sample is one when it
// is below its only neighbour (a competing depth at the edge of the sweep).
MSP_HD bool IsStrictLocalMinimum(const float* curve, int n, int i) {
  const bool below_left = i == 0 || curve[i] < curve[i - 1];
  const bool below_right = i == n - 1 || curve[i] < curve[i + 1];
  return n > 1 && below_left && below_right;
}

// Classifies a cost curve of n samples whose centre is sample n / 2.
MSP_HD uint8_t ClassifyCostCurve(const float* curve, int n, const ReliabilityParams& params) {
  int lowest = -1;
  int num_minima = 0;
  for (int i = 0; i < n; ++i) {
    if (!IsStrictLocalMinimum(curve, n, i)) continue;
    ++num_minima;
    if (lowest < 0 || curve[i] < curve[lowest]) lowest = i;
  }
  if (lowest < 0) return kUnreliable;  // flat curve: no minimum at all
  const int offset = lowest - n / 2;
  if (offset > params.radius || -offset > params.radius) return kUnreliable;
  if (curve[lowest] > params.max_minimum_cost) return kUnreliable;
  if (num_minima == 1) {
    return curve[lowest] <= params.single_min_cost ? kReliable : kUnreliable;
  }
  // Several minima: the lowest must stand out from the nearest competitor.
  float second = 1e30f;
  for (int i = 0; i < n; ++i) {
    if (i != lowest && IsStrictLocalMinimum(curve, n, i) && curve[i] < second) second = curve[i];
  }
  return second - curve[lowest] > params.min_spread ? kReliable : kUnreliable;
}

// Lower bounds serve only this far above the costs a verdict compares.
constexpr float kBoundMargin = 1e-3f;

// ClassifyCostCurve over a curve whose samples are computed on demand (each
// at most once) by `sampler.AtLeast(i, floor)`: the cost of sample i, or,
// when that cost exceeds `floor`, possibly only a lower bound above `floor`.
// It decides with the same answer, but most unreliable pixels need only the
// central samples: the pixel can only be reliable when the lowest minimum
// within `radius` of the centre is low enough, and the outer samples are
// then scanned only until a minimum there beats it or comes within
// `min_spread` of it. A reliable pixel needs the whole curve; of the outer
// samples it needs only those that could compete (lower bounds above
// best + min_spread rule out the others).
template <typename Sampler>
class LazyCostCurve {
 public:
  MSP_HD LazyCostCurve(Sampler* sampler, int n) : sampler_(sampler), n_(n) {
    for (int i = 0; i < n; ++i) known_[i] = false;
  }
  // The cost of sample i, or, once AllowBoundsAbove(floor) was called and
  // the cost exceeds that floor, possibly a lower bound above it.
  MSP_HD float At(int i) { return AtLeast(i, floor_); }
  // The sampler's contract, so that a curve can serve as another's sampler.
  MSP_HD float AtLeast(int i, float floor) {
    if (!known_[i] || (!exact_[i] && !(value_[i] > floor))) {
      value_[i] = sampler_->AtLeast(i, floor);
      known_[i] = true;
      exact_[i] = floor >= kUnboundedCost || !(value_[i] > floor);  // bounds lie above it
    }
    return value_[i];
  }
  // From now on At() may return lower bounds for costs above `floor`.
  MSP_HD void AllowBoundsAbove(float floor) { floor_ = floor; }
  // IsStrictLocalMinimum on the lazily sampled curve.
  MSP_HD bool IsMinimum(int i) {
    if (n_ < 2) return false;
    const bool below_left = i == 0 || At(i) < At(i - 1);
    return below_left && (i == n_ - 1 || At(i) < At(i + 1));
  }
  MSP_HD int size() const { return n_; }

 private:
  Sampler* sampler_;
  int n_;
  float floor_ = kUnboundedCost;
  float value_[kMaxSweepSamples];
  bool known_[kMaxSweepSamples];
  bool exact_[kMaxSweepSamples];
};

template <typename Sampler>
MSP_HD uint8_t ClassifyCostCurveLazily(LazyCostCurve<Sampler>& curve,
                                       const ReliabilityParams& params) {
  const int n = curve.size(), centre = n / 2;
  const int lo = centre - params.radius < 0 ? 0 : centre - params.radius;
  const int hi = centre + params.radius > n - 1 ? n - 1 : centre + params.radius;
  int lowest = -1, num_minima = 0;
  for (int i = lo; i <= hi; ++i) {
    if (!curve.IsMinimum(i)) continue;
    ++num_minima;
    if (lowest < 0 || curve.At(i) < curve.At(lowest)) lowest = i;
  }
  // No central minimum, or too high a one: the lowest minimum of the whole
  // curve is either outside the radius or this one, unreliable either way.
  if (lowest < 0) return kUnreliable;
  const float best = curve.At(lowest);
  if (best > params.max_minimum_cost) return kUnreliable;
  float second = 1e30f;
  for (int i = lo; i <= hi; ++i) {
    if (i != lowest && curve.IsMinimum(i) && curve.At(i) < second) second = curve.At(i);
  }
  // Past here the verdict turns on two questions: does an outer minimum lie
  // within min_spread of the best, and does any other minimum exist at all.
  // Once the second is settled (a minimum other than the best was found
  // exactly), or no longer matters (a single minimum this low is reliable
  // too), samples above best + min_spread need no exact cost: a lower bound
  // above that can neither be a competitor nor hide one next to it (a
  // competitor lies below its neighbours either way). The margin keeps
  // float rounding of the spread test below from flipping.
  const float floor = best + params.min_spread + kBoundMargin;
  if (best <= params.single_min_cost || num_minima >= 2) curve.AllowBoundsAbove(floor);
  // The outer samples nearest the centre first, alternating sides: a
  // competing minimum found anywhere ends the scan, and the verdict does not
  // depend on the order.
  int right = hi + 1, left = lo - 1;
  while (right < n || left >= 0) {
    const bool take_right = right < n && (left < 0 || right - hi <= lo - left);
    const int i = take_right ? right++ : left--;
    if (!curve.IsMinimum(i)) continue;
    ++num_minima;
    const float v = curve.At(i);
    // Lower (or as low and further left): the lowest minimum is outside.
    if (v < best || (v == best && i < lowest)) return kUnreliable;
    if (v - best <= params.min_spread) return kUnreliable;  // second - best can only shrink
    if (v < second) second = v;
    curve.AllowBoundsAbove(floor);  // another minimum exists
  }
  if (num_minima == 1) return best <= params.single_min_cost ? kReliable : kUnreliable;
  return second - best > params.min_spread ? kReliable : kUnreliable;
}

// The cost curve of pixel (col, row): its normal fixed, depths at disparity
// offsets -half_width..half_width px (b = mean baseline to the selected
// views), each scored with uniform weights over the view mask. The costs are
// photometric whatever the pass: the thresholds are NCC costs.
class CostCurveSampler {
 public:
  // False when the pixel is "unknown": window over the border, no depth, or
  // no selected view.
  MSP_HD bool Prepare(const PassParams& p, int col, int row, int half_width = kCurveHalfWidth) {
    p_ = &p;
    half_width_ = half_width;
    const PixelStateView& s = p.state;
    const int r = p.ncc.window_radius;
    if (col < r || row < r || col + r >= s.width || row + r >= s.height) return false;
    const int i = s.Index(col, row);
    current_ = s.Get(i);
    const uint32_t mask = s.mask[i];
    if (!(current_.depth > 0.0f) || mask == 0u) return false;
    focal_baseline_ = p.ref_camera.fx * MeanBaseline(p, mask);
    if (!(focal_baseline_ > 0.0f)) return false;
    MaskWeights(p, mask, weights_);
    total_weight_ = TotalWeight(weights_, p.num_src);
    PrepareWindow(p, col, row, &window_);
    for (int k = 0; k <= 2 * half_width; ++k) known_[k] = false;
    return true;
  }
  // The plane of sample k (0..2 half_width): the pixel's, at offset k - half_width.
  MSP_HD PlaneHypothesis Plane(int k) const {
    if (k == half_width_) return current_;
    PlaneHypothesis h = current_;
    h.depth = DepthAtDisparityOffset(focal_baseline_, current_.depth,
                                     static_cast<float>(k - half_width_));
    return h;
  }
  // The view-weighted photometric cost of sample k (AggregateCost of the
  // views' PhotometricViewCost), kMaxCost for a depth out of range; or, when it
  // exceeds `floor`, possibly a lower bound above `floor` (ScoreBlock).
  MSP_HD float AtLeast(int k, float floor) {
    if (!known_[k] || (!exact_[k] && !(cost_[k] > floor))) ScoreBlock(k, floor);
    return cost_[k];
  }
  MSP_HD float At(int k) { return AtLeast(k, kUnboundedCost); }
  MSP_HD const float* weights() const { return weights_; }

 private:
  // Scores the block of kWindowLanes samples that holds sample k, blocks
  // counted from the centre, all at once per view (WindowNccCosts):
  // consecutive disparities land about a pixel apart in the source, so the
  // lanes read the same cache lines. Views of weight 0 add nothing to the
  // aggregate and are skipped. The costs are weighted means of costs >= 0,
  // so the views summed so far bound every lane from below: once every lane
  // is above `floor`, the other views are left out and the lanes keep their
  // bounds.
  MSP_HD void ScoreBlock(int k, float floor) {
    const int offset = k - half_width_;
    const int block =
        offset >= 0 ? offset / kWindowLanes : -((kWindowLanes - 1 - offset) / kWindowLanes);
    const int first =
        half_width_ + block * kWindowLanes < 0 ? 0 : half_width_ + block * kWindowLanes;
    const int end = half_width_ + (block + 1) * kWindowLanes;
    const int count = (end > 2 * half_width_ + 1 ? 2 * half_width_ + 1 : end) - first;
    PlaneHypothesis h[kWindowLanes];
    bool in_range[kWindowLanes];
    for (int l = 0; l < count; ++l) {
      h[l] = Plane(first + l);
      in_range[l] = DepthInRange(*p_, h[l].depth);
    }
    PreparedPlane planes[kWindowLanes];
    const uint32_t lanes = PreparePlanes(*p_, window_, h, in_range, count, planes);
    float sum[kWindowLanes] = {};
    bool exact = true;
    for (int j = 0; j < p_->num_src && total_weight_ > 0.0f; ++j) {
      if (!(weights_[j] > 0.0f)) continue;
      Mat3 H[kWindowLanes];
      float ncc[kWindowLanes];
      CandidateWindowCosts(*p_, window_, j, planes, lanes, count, H, ncc);
      bool above = floor < kUnboundedCost;
      for (int l = 0; l < count; ++l) {
        sum[l] += weights_[j] * ncc[l];
        above = above && (!in_range[l] || sum[l] / total_weight_ > floor);
      }
      if (above) {
        exact = false;
        break;
      }
    }
    for (int l = 0; l < count; ++l) {
      cost_[first + l] = in_range[l] && total_weight_ > 0.0f ? sum[l] / total_weight_ : kMaxCost;
      known_[first + l] = true;
      exact_[first + l] = exact || !in_range[l];
    }
  }

  const PassParams* p_ = nullptr;
  int half_width_ = kCurveHalfWidth;
  PlaneHypothesis current_;
  float focal_baseline_ = 0.0f;
  float weights_[kMaxSourceViews];
  float total_weight_ = 0.0f;
  RefWindow window_;
  float cost_[kMaxSweepSamples];
  bool known_[kMaxSweepSamples];
  bool exact_[kMaxSweepSamples];
};

// kReliable / kUnreliable / kUnknown for pixel (col, row) after a pass.
MSP_HD uint8_t ClassifyPixel(const PassParams& p, int col, int row,
                             const ReliabilityParams& params) {
  CostCurveSampler sampler;
  if (!sampler.Prepare(p, col, row)) return kUnknown;
  LazyCostCurve<CostCurveSampler> curve(&sampler, kCurveSamples);
  return ClassifyCostCurveLazily(curve, params);
}

}  // namespace core
}  // namespace msp

// ACMM multi-view aggregation with view selection: per view, a likelihood from
// how many candidate hypotheses match well or badly, a prior from the view's
// selection in the previous iteration, then Monte-Carlo draws give the weights.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/math/hd.h"
#include "core/math/limits.h"
#include "core/math/rng.h"

namespace msp {
namespace core {

// ACMM's constants: the good-match threshold starts at 0.8 and decays with
// the iteration; a cost above 1.2 is a clear mismatch.
constexpr float kGoodCostStart = 0.8f;
constexpr float kGoodCostDecay = 90.0f;
constexpr float kBadCost = 1.2f;
constexpr int kMinGoodCandidates = 3;         // "good > 2"
constexpr int kMaxBadCandidates = 2;          // "bad < 3"
constexpr float kLikelihoodSigma2x2 = 0.18f;  // 2 * 0.3^2
constexpr float kFallbackSigma2x2 = 0.32f;    // 2 * 0.4^2
constexpr float kSelectedPrior = 0.9f;
constexpr float kUnselectedPrior = 0.1f;

MSP_HD float GoodCostThreshold(int iteration) {
  return kGoodCostStart * expf(-static_cast<float>(iteration * iteration) / kGoodCostDecay);
}

// costs[k * stride + j]: cost of candidate k in view j (k < num_candidates).
// Writes weights[j] (summing to 1) and returns the set of views drawn at
// least once. `previous_mask` is the pixel's selection of the last iteration.
MSP_HD uint32_t SelectViews(const float* costs, int num_candidates, int num_views, int stride,
                            int iteration, uint32_t previous_mask, int num_samples, Rng* rng,
                            float* weights) {
  const float tau = GoodCostThreshold(iteration);
  float likelihood[kMaxSourceViews];
  float cumulative[kMaxSourceViews];  // running sums of the likelihoods
  float total = 0.0f;
  for (int j = 0; j < num_views; ++j) {
    int good = 0, bad = 0;
    float sum = 0.0f;
    for (int k = 0; k < num_candidates; ++k) {
      const float c = costs[k * stride + j];
      if (c < tau) {
        ++good;
        sum += expf(-c * c / kLikelihoodSigma2x2);
      } else if (c > kBadCost) {
        ++bad;
      }
    }
    float l = 0.0f;
    if (good >= kMinGoodCandidates && bad <= kMaxBadCandidates) {
      l = sum / good;
    } else if (bad <= kMaxBadCandidates) {
      l = expf(-tau * tau / kFallbackSigma2x2);
    }
    l *= ((previous_mask >> j) & 1u) ? kSelectedPrior : kUnselectedPrior;
    likelihood[j] = l;
    total += l;
    cumulative[j] = total;
  }
  uint32_t mask = 0u;
  for (int j = 0; j < num_views; ++j) weights[j] = 0.0f;
  if (!(total > 0.0f)) {  // every view mismatches: fall back to equal weights
    for (int j = 0; j < num_views; ++j) weights[j] = 1.0f / num_views;
    return num_views >= 32 ? 0xFFFFFFFFu : ((1u << num_views) - 1u);
  }
  for (int s = 0; s < num_samples; ++s) {
    // The first view whose running sum exceeds u, the last if none does.
    // The sums never decrease, so that view's index is the number of sums
    // at or below u: counted without a branch, whose outcome is random.
    const float u = rng->Uniform() * total;
    int pick = 0;
    for (int j = 0; j < num_views; ++j) pick += cumulative[j] <= u;
    if (pick > num_views - 1) pick = num_views - 1;
    // Rounding can leave u past the last non-zero view: step back to one.
    while (pick > 0 && likelihood[pick] <= 0.0f) --pick;
    weights[pick] += 1.0f;
    mask |= 1u << pick;
  }
  for (int j = 0; j < num_views; ++j) weights[j] /= num_samples;
  return mask;
}

// Weighted mean of one candidate's per-view costs.
MSP_HD float AggregateCost(const float* costs, const float* weights, int num_views) {
  float c = 0.0f, w = 0.0f;
  for (int j = 0; j < num_views; ++j) {
    c += weights[j] * costs[j];
    w += weights[j];
  }
  return w > 0.0f ? c / w : kMaxCost;
}

}  // namespace core
}  // namespace msp

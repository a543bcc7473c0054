// Disparity-sampling synergistic 3D optimization (paper "Sampling Pixel
// Randomization" and "3D Cost Profile Optimization", eqs. 8-9;
// docs/method.md section 7). A fixed grid of sampling pixels may
// misrepresent a sub-patch, so a lane's samples lie at random inside its
// sub-patches instead. A solution (the samples of every lane) is a pure
// function of a 32-bit word, so a pixel keeps its solution from one iteration
// to the next as one number. The optimization perturbs the solution in use J
// times (or draws J new ones), profiles the deformable cost of each over mu
// disparities around the pixel's depth, keeps the solution whose profile is
// lowest and most peaked (eq. 9), and offers the best depth of that profile
// as a candidate.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/deformable/anchor_clusters.h"
#include "core/deformable/anchor_windows.h"
#include "core/deformable/anchors.h"
#include "core/deformable/deformable_cost.h"
#include "core/math/hd.h"
#include "core/math/rng.h"
#include "core/patch_match/local_refine.h"
#include "core/patch_match/patch_match_kernel.h"

namespace msp {
namespace core {

// Paper defaults: J = 6 solutions, mu = 5 disparities 1 px apart, omega = 0.01.
constexpr int kDefaultSamplingSolutions = 6;
constexpr int kDefaultDisparitySamples = 5;
constexpr float kDefaultDisparityStep = 1.0f;
constexpr float kDefaultVarianceWeight = 0.01f;
// The centre windows of all disparities are scored in one batch of lanes.
constexpr int kMaxDisparitySamples = kWindowLanes - 1;  // odd
constexpr int kMaxSamplingSolutions = 32;
// Floor of (c_i - c_bar)^2 in eq. 9: NCC costs differing by less than 0.01
// are noise, and a flat profile must not score infinity.
constexpr float kMinSquaredDeviation = 1e-4f;
// A sample drawn onto a pixel its sub-patch already samples is drawn again,
// at most this many times (a sub-patch smaller than its sample count repeats).
constexpr int kMaxSampleRedraws = 4;
// Salt of the sampling streams: apart from every other stream of the pixel.
constexpr uint32_t kSamplingSeedSalt = 0x5A3D1E97u;

struct SynergyParams {
  int solutions;           // J, drawn per optimization
  int disparity_samples;   // mu, odd, 1..kMaxDisparitySamples
  float disparity_step;    // delta, px of disparity
  float variance_weight;   // omega; 0 = no variance term
  bool profile_cost_term;  // false = F without the sum of costs
  // The paper's iterative local search: the solution in use competes with J
  // perturbations of itself, each re-drawing one lane's samples (LaneLayout);
  // false = J independent draws that replace it.
  bool local_search = false;
};

MSP_HD SynergyParams DefaultSynergyParams() {
  return SynergyParams{kDefaultSamplingSolutions,
                       kDefaultDisparitySamples,
                       kDefaultDisparityStep,
                       kDefaultVarianceWeight,
                       true,
                       false};
}

// Local search solutions: a 32-bit word holds a 4-bit layout index per lane
// (8 lanes), and lane c's samples are a pure function of (the pixel's key of
// the pass, c, its index), so a solution's neighbours are the words that
// differ in one lane's index: one sub-patch re-sampled, the others kept.
constexpr int kLayoutBits = 4;
constexpr uint32_t kLayoutMask = (1u << kLayoutBits) - 1u;
static_assert(kLayoutBits * kMaxAnchors == 32, "one layout index per lane in a 32-bit word");

MSP_HD uint32_t LaneLayout(uint32_t solution, int lane) {
  return (solution >> (kLayoutBits * lane)) & kLayoutMask;
}

// Eq. 9: F = sum_i c_i + omega sum_i (c_i - c_bar)^-2 over the mu costs of a
// profile, each squared deviation floored at kMinSquaredDeviation. Lower is
// better: low costs, and a profile that stands out of its mean everywhere
// (a sharp minimum) rather than a flat one.
MSP_HD float ProfileObjective(const float* c, int mu, const SynergyParams& sp) {
  float sum = 0.0f;
  for (int i = 0; i < mu; ++i) sum += c[i];
  float f = sp.profile_cost_term ? sum : 0.0f;
  if (sp.variance_weight > 0.0f) {
    const float mean = sum / static_cast<float>(mu);
    float inverse = 0.0f;
    for (int i = 0; i < mu; ++i) {
      const float d = c[i] - mean;
      inverse += 1.0f / fmaxf(d * d, kMinSquaredDeviation);
    }
    f += sp.variance_weight * inverse;
  }
  return f;
}

// The solution a pixel starts a pass with (x_0).
MSP_HD uint32_t InitialSamplingSolution(const PassParams& p, uint32_t pixel) {
  return static_cast<uint32_t>(
      RngKey(p.seed ^ kSamplingSeedSalt, p.image_id, p.pass_id, 0u, pixel));
}

// Solution j (1..J) drawn by the optimization of `iteration`.
MSP_HD uint32_t DrawnSamplingSolution(const PassParams& p, int iteration, uint32_t pixel, int j) {
  const uint64_t key = RngKey(p.seed ^ kSamplingSeedSalt, p.image_id, p.pass_id,
                              static_cast<uint32_t>(iteration) + 1u, pixel);
  return static_cast<uint32_t>(Mix64(key ^ static_cast<uint64_t>(j)));
}

// Perturbation j (1..J) of `solution` in `iteration` (local search): one
// lane of the `num_lanes` in use takes another of its 16 layouts.
MSP_HD uint32_t PerturbedSamplingSolution(const PassParams& p, int iteration, uint32_t pixel, int j,
                                          int num_lanes, uint32_t solution) {
  Rng rng = MakeRng(Mix64(RngKey(p.seed ^ kSamplingSeedSalt, p.image_id, p.pass_id,
                                 static_cast<uint32_t>(iteration) + 1u, pixel) ^
                          (0x100000000ull * static_cast<uint64_t>(j))));
  const int lanes = ClampInt(num_lanes, 1, kMaxAnchors);
  const int lane =
      ClampInt(static_cast<int>(rng.Uniform() * static_cast<float>(lanes)), 0, lanes - 1);
  // One of the 15 other layouts, uniformly.
  const uint32_t step =
      1u + static_cast<uint32_t>(ClampInt(static_cast<int>(rng.Uniform() * kLayoutMask), 0,
                                          static_cast<int>(kLayoutMask) - 1));
  const uint32_t shift = static_cast<uint32_t>(kLayoutBits * lane);
  const uint32_t layout = (LaneLayout(solution, lane) + step) & kLayoutMask;
  return (solution & ~(kLayoutMask << shift)) | (layout << shift);
}

// The key of a pixel's lane layouts in a pass (local search).
MSP_HD uint64_t LayoutKey(const PassParams& p, uint32_t pixel) {
  return RngKey(p.seed ^ kSamplingSeedSalt, p.image_id, p.pass_id, 0xFFFFu, pixel);
}

// Offsets of a solution: sample t of a sub-patch of half side h uniform on
// its (2h + 1)^2 pixels, redrawn when the sub-patch already samples it.
// With a layout key (local search), each lane draws from its own stream,
// keyed by the lane and its layout index in the solution word; else one
// stream, seeded by the solution, runs through all lanes.
struct RandomOffsets {
  Rng rng;
  bool per_lane = false;
  uint64_t layout_key = 0;
  uint32_t solution = 0;
  int lane = -1;
  int taken_x[kClusterLaneSamples];
  int taken_y[kClusterLaneSamples];
  MSP_HD int Draw(int h) {
    const int span = 2 * h + 1;
    const int v = static_cast<int>(rng.Uniform() * static_cast<float>(span));
    return (v < span ? v : span - 1) - h;
  }
  MSP_HD void operator()(int c, int t, int, int h, int* dx, int* dy) {
    if (per_lane && c != lane) {
      lane = c;
      rng = MakeRng(Mix64(layout_key ^ (static_cast<uint64_t>(c) << 8) ^
                          static_cast<uint64_t>(LaneLayout(solution, c))));
    }
    const bool room = t < (2 * h + 1) * (2 * h + 1);
    bool taken = true;
    for (int r = 0; r <= kMaxSampleRedraws && taken; ++r) {
      *dx = Draw(h);
      *dy = Draw(h);
      taken = false;
      for (int u = 0; u < t && u < kClusterLaneSamples; ++u) {
        taken = taken || (taken_x[u] == *dx && taken_y[u] == *dy);
      }
      taken = taken && room;
    }
    if (t < kClusterLaneSamples) {
      taken_x[t] = *dx;
      taken_y[t] = *dy;
    }
  }
};

// The samples of solution `seed` (ClusterLaneSamples with RandomOffsets);
// `layout_key` != 0: a local search word (LayoutKey).
MSP_HD void RandomClusterSamples(const AnchorSet& anchors, const AnchorClusters& clusters,
                                 int radius, int width, int height, uint32_t seed, LaneSamples* out,
                                 uint64_t layout_key = 0) {
  RandomOffsets offsets;
  offsets.rng = MakeRng(Mix64(static_cast<uint64_t>(seed) ^ kSamplingSeedSalt));
  offsets.per_lane = layout_key != 0;
  offsets.layout_key = layout_key;
  offsets.solution = seed;
  ClusterLaneSamples(anchors, clusters, radius, width, height, offsets, out);
}

// The anchor windows of solution `seed` of pixel `pixel`.
MSP_HD void PrepareSampledWindows(const PassParams& p, const AnchorSet& anchors,
                                  const AnchorClusters& clusters, const DeformableParams& d,
                                  const SynergyParams& sp, uint32_t pixel, uint32_t seed,
                                  AnchorWindows* w) {
  LaneSamples samples;
  RandomClusterSamples(anchors, clusters, d.anchor_window_radius, p.ref_image.width,
                       p.ref_image.height, seed, &samples,
                       sp.local_search ? LayoutKey(p, pixel) : 0);
  PrepareAnchorWindows(p.ref_image, samples, d.anchor_window_radius, w);
}

// The cost profiles of one pixel's sampling solutions (eq. 8): its plane's
// normal, mu depths d_i = d + (i - (mu + 1) / 2) delta in disparity,
// disparity = f b / depth with b the mean baseline to the pixel's selected
// views (as the reliability curve), and per solution the deformable
// photometric cost (eq. 3, lanes = the clusters' sampled sub-patches)
// averaged over those views with uniform weights. The centre window's costs
// do not depend on the solution: Prepare scores them once.
struct ProfileScorer {
  int mu = 0, middle = 0;
  uint32_t lanes = 0u;  // disparities in range
  PlaneHypothesis h[kWindowLanes];
  int num_views = 0;
  int views[kMaxSourceViews];
  float weights[kMaxSourceViews];
  float total_weight = 0.0f;
  Mat3 H[kMaxSourceViews][kWindowLanes];
  float centre_cost[kMaxSourceViews][kWindowLanes];
  uint32_t take[kMaxSourceViews];  // disparities where the anchors take part, per view

  // False when the pixel has no depth, selected view or cluster.
  MSP_HD bool Prepare(const PassParams& p, int col, int row, const RefWindow& centre,
                      const AnchorClusters& clusters, const SynergyParams& sp) {
    const PixelStateView& s = p.state;
    const int i = s.Index(col, row);
    const PlaneHypothesis current = s.Get(i);
    const uint32_t mask = s.mask[i];
    if (!(current.depth > 0.0f) || mask == 0u || clusters.count == 0) return false;
    const float focal_baseline = p.ref_camera.fx * MeanBaseline(p, mask);
    if (!(focal_baseline > 0.0f)) return false;
    MaskWeights(p, mask, weights);
    total_weight = TotalWeight(weights, p.num_src);
    mu = ClampInt(sp.disparity_samples, 1, kMaxDisparitySamples);
    middle = (mu - 1) / 2;
    bool in_range[kWindowLanes];
    for (int k = 0; k < mu; ++k) {
      h[k] = current;
      if (k != middle) {
        h[k].depth = DepthAtDisparityOffset(focal_baseline, current.depth,
                                            static_cast<float>(k - middle) * sp.disparity_step);
      }
      in_range[k] = DepthInRange(p, h[k].depth);
    }
    PreparedPlane planes[kWindowLanes];
    lanes = PreparePlanes(p, centre, h, in_range, mu, planes);
    if (lanes == 0u || !(total_weight > 0.0f)) return false;
    // Whether the anchors take part (AnchorsTakePart's rule) does not
    // depend on the solution either.
    num_views = 0;
    for (int j = 0; j < p.num_src; ++j) {
      if (!(weights[j] > 0.0f)) continue;
      const int v = num_views++;
      views[v] = j;
      CandidateWindowCosts(p, centre, j, planes, lanes, mu, H[v], centre_cost[v]);
      take[v] = 0u;
      for (int k = 0; k < mu; ++k) {
        const bool part =
            ((lanes >> k) & 1u) &&
            !(centre_cost[v][k] >= kMaxCost && !CentreInSource(H[v][k], p.src[j].image, col, row));
        take[v] |= part ? 1u << k : 0u;
      }
    }
    return true;
  }

  // The cost profile of solution `seed` (kMaxCost out of range).
  MSP_HD void Profile(const PassParams& p, const AnchorSet& anchors, const AnchorClusters& clusters,
                      const DeformableParams& d, const SynergyParams& sp, uint32_t pixel,
                      uint32_t seed, float* profile) const {
    AnchorWindows w;
    PrepareSampledWindows(p, anchors, clusters, d, sp, pixel, seed, &w);
    const NccParams anchor_ncc = AnchorNccParams(p.ncc, d);
    for (int k = 0; k < mu; ++k) {
      if (!((lanes >> k) & 1u)) {
        profile[k] = kMaxCost;
        continue;
      }
      float sum = 0.0f;
      for (int v = 0; v < num_views; ++v) {
        const int j = views[v];
        float cost = centre_cost[v][k];
        if ((take[v] >> k) & 1u) {
          const float lanes_sum =
              AnchorCostSum(w, p.ref_image, p.src[j].image, H[v][k], anchor_ncc);
          cost = MixDeformable(cost, lanes_sum, w.count, d);
        }
        sum += weights[j] * cost;
      }
      profile[k] = sum / total_weight;
    }
  }
};

// Solution `index` of an optimization of solution `in_use`: with local
// search 0 is `in_use` and 1..J its perturbations; else 1..J are drawn anew.
MSP_HD uint32_t CompetingSolution(const PassParams& p, int iteration, uint32_t pixel,
                                  const SynergyParams& sp, int num_lanes, uint32_t in_use,
                                  int index) {
  if (!sp.local_search) return DrawnSamplingSolution(p, iteration, pixel, index);
  if (index == 0) return in_use;
  return PerturbedSamplingSolution(p, iteration, pixel, index, num_lanes, in_use);
}

// The 3D optimization of pixel (col, row) in `iteration` (ProfileScorer).
// With local search (the paper's "random perturbation on current
// solutions"), the solution in use, *solution, and J perturbations of it
// compete (the one in use wins ties), so iteration after iteration one
// solution improves; without, J independent draws compete (the first wins
// ties) and the winner replaces *solution, which is not scored. The solution
// of lowest F (eq. 9) is kept. Returns true with *candidate = the
// lowest-cost depth of the chosen profile when that is not the current
// depth; false, with *solution unchanged, when the pixel has no depth,
// selected view or cluster.
MSP_HD bool OptimizeSampling(const PassParams& p, int col, int row, int iteration,
                             const RefWindow& centre, const AnchorSet& anchors,
                             const AnchorClusters& clusters, const DeformableParams& d,
                             const SynergyParams& sp, uint32_t* solution,
                             PlaneHypothesis* candidate) {
  ProfileScorer scorer;
  if (!scorer.Prepare(p, col, row, centre, clusters, sp)) return false;
  const int num_solutions = ClampInt(sp.solutions, 1, kMaxSamplingSolutions);
  const uint32_t pixel = static_cast<uint32_t>(p.state.Index(col, row));
  const uint32_t in_use = *solution;
  const int first = sp.local_search ? 0 : 1;
  float best_f = 0.0f;
  float best_profile[kWindowLanes];
  for (int sol = first; sol <= num_solutions; ++sol) {
    const uint32_t seed = CompetingSolution(p, iteration, pixel, sp, clusters.count, in_use, sol);
    float profile[kWindowLanes];
    scorer.Profile(p, anchors, clusters, d, sp, pixel, seed, profile);
    const float f = ProfileObjective(profile, scorer.mu, sp);
    if (sol == first || f < best_f) {
      best_f = f;
      *solution = seed;
      for (int k = 0; k < scorer.mu; ++k) best_profile[k] = profile[k];
    }
  }
  int best = scorer.middle;
  for (int k = 0; k < scorer.mu; ++k) {
    if (best_profile[k] < best_profile[best]) best = k;
  }
  if (best == scorer.middle || !(best_profile[best] < kMaxCost)) return false;
  *candidate = scorer.h[best];
  return true;
}

// What a pixel's deformable update does with its samples: solution ==
// nullptr keeps the fixed grid (no synergistic optimization); else the
// lanes sample solution *solution, which the 3D optimization replaces when
// `optimize` is set.
struct PixelSampling {
  uint32_t* solution = nullptr;
  bool optimize = false;
  SynergyParams params = DefaultSynergyParams();
};

}  // namespace core
}  // namespace msp

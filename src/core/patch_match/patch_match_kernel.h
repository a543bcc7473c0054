// The per-pixel steps of conventional PatchMatch MVS (ACMM lineage), written
// once for the CPU driver and the CUDA kernels: the cost of a hypothesis in
// every view (one plane, or a batch of candidate planes scored together), its
// view-weighted aggregate with an early stop, initialisation, and the update
// of a pixel by propagation with view selection and refinement. The local
// disparity sweep (local_refine.h) and the output filter (output_filter.h)
// build on these costs. All state lives in PassParams' arrays.
#pragma once

#include <cstdint>

#include "core/cost/evaluation_count.h"
#include "core/cost/ncc.h"
#include "core/cost/window_batch.h"
#include "core/cost/window_cost.h"
#include "core/math/camera.h"
#include "core/math/hd.h"
#include "core/math/homography.h"
#include "core/math/image_view.h"
#include "core/math/limits.h"
#include "core/math/plane.h"
#include "core/math/rng.h"
#include "core/patch_match/checkerboard.h"
#include "core/patch_match/geometric_cost.h"
#include "core/patch_match/view_selection.h"

namespace msp {
namespace core {

// Views whose costs average into the initial cost of a hypothesis (no view
// selection exists yet): the best few, as a pixel is rarely seen by all.
constexpr int kInitialTopViews = 3;
// Draw stream ids: separate streams for the steps of one pixel update.
constexpr uint32_t kStreamSelect = 1, kStreamRefine = 2, kStreamRestart = 3;

struct SourceView {
  Camera camera;
  RelativePose rel;  // reference camera frame -> this camera's frame
  ImageView image;
  ImageView depth;  // previous-pass depth (geometric passes), else data == nullptr
};

// Per-pixel state of the reference image: plane, aggregated cost, view mask.
struct PixelStateView {
  float* depth;
  float* normal;  // 3 planes (nx, ny, nz) of width * height
  float* cost;
  uint32_t* mask;
  int width;
  int height;
  MSP_HD int Index(int col, int row) const { return row * width + col; }
  MSP_HD PlaneHypothesis Get(int i) const {
    const int n = width * height;
    return PlaneHypothesis{depth[i], Vec3{normal[i], normal[n + i], normal[2 * n + i]}};
  }
  MSP_HD void Set(int i, const PlaneHypothesis& h) const {
    const int n = width * height;
    depth[i] = h.depth;
    normal[i] = h.normal.x;
    normal[n + i] = h.normal.y;
    normal[2 * n + i] = h.normal.z;
  }
};

struct PassParams {
  Camera ref_camera;
  ImageView ref_image;
  SourceView src[kMaxSourceViews];
  int num_src;
  NccParams ncc;
  float depth_min;
  float depth_max;
  int geometric;         // 1: add the geometric consistency term
  float geom_lambda;     // weight of the reprojection error
  float geom_max_error;  // pixels; the error is clamped here
  // > 0: the error is the depth disagreement in these units (geometric_cost.h)
  float geom_depth_unit = 0.0f;
  int num_samples;       // Monte-Carlo view draws
  float perturb_depth;   // relative depth perturbation of refinement
  float perturb_normal;  // radians
  uint32_t seed;
  uint32_t image_id;
  uint32_t pass_id;
  int weighted_views_only;  // 1: propagation scores only the views of the last selection
  // Disparity pixels each side of LocalRefinePixel's sweep; the refinement
  // that also classifies (refine_and_classify.h) always sweeps kLocalRefineRadius.
  int refine_radius = kLocalRefineRadius;
  // 1 at a pixel whose matching window holds nothing to match (UnlitPixels,
  // src/patch_match/unlit_pixels.h); null when no pixel is so.
  const uint8_t* unlit = nullptr;
  // 1 at a pixel that keeps the plane it has: no sweep or local refinement
  // moves it, while it is scored, proposes its plane and is filtered as any
  // (the finest round's weakly textured pixels, held_pixels.h); null when none.
  const uint8_t* held = nullptr;
  // A region label per reference pixel (0 = unlabelled): a matching window
  // keeps only its centre's region (PrepareRefWindow); null: whole windows.
  const int32_t* window_regions = nullptr;
  PixelStateView state;
};

// True at a pixel with nothing to match: it keeps no plane (depth 0, which
// no neighbour propagates and the outputs leave empty), and no step scores it.
MSP_HD bool IsUnlit(const PassParams& p, int i) { return p.unlit != nullptr && p.unlit[i] != 0u; }

// True at a pixel whose plane the sweeps leave as it is (PassParams::held).
MSP_HD bool IsHeld(const PassParams& p, int i) { return p.held != nullptr && p.held[i] != 0u; }

// Pixel i without a plane: depth 0, the highest cost, no selected views.
MSP_HD void ClearPixel(const PixelStateView& s, int i) {
  s.Set(i, PlaneHypothesis{0.0f, Vec3{0.0f, 0.0f, -1.0f}});
  s.cost[i] = kMaxCost;
  s.mask[i] = 0u;
}

MSP_HD bool DepthInRange(const PassParams& p, float depth) {
  return depth >= p.depth_min && depth <= p.depth_max;
}

// The matching window of pixel (col, row), prepared once per pixel update.
MSP_HD void PrepareWindow(const PassParams& p, int col, int row, RefWindow* w) {
  PrepareRefWindow(p.ref_image, col, row, p.ncc.window_radius, p.ncc.window_step, p.ncc.bilateral,
                   p.window_regions, w);
}

// A hypothesis as every source view scores it at pixel (col, row): the
// plane's part of the homography, computed once instead of once per view,
// and the depth the geometric term reprojects.
struct PreparedPlane {
  int valid;  // the plane passes in front of the camera at the pixel
  PlaneWarp warp;
  float depth;
};

MSP_HD PreparedPlane PreparePlane(const PassParams& p, int col, int row, const PlaneHypothesis& h) {
  PreparedPlane prepared;
  const Vec3 X =
      BackProject(p.ref_camera, static_cast<float>(col), static_cast<float>(row), h.depth);
  const float dist = -Dot(h.normal, X);  // PlaneDistance
  prepared.valid = dist > 0.0f;
  if (!prepared.valid) return prepared;
  prepared.warp = MakePlaneWarp(p.ref_camera, h.normal, dist);
  prepared.depth = h.depth;
  return prepared;
}

// Geometric consistency term of source view j (0 in photometric passes).
MSP_HD float GeometricTerm(const PassParams& p, int j, int col, int row, float depth) {
  const SourceView& s = p.src[j];
  if (!p.geometric || s.depth.data == nullptr) return 0.0f;
  return p.geom_lambda * ComposedReprojectionError(s.rel, s.camera, s.depth, col, row, depth,
                                                   p.geom_max_error, p.geom_depth_unit);
}

// The photometric cost (1 - NCC) of a prepared hypothesis at the centre of
// window w in source view j; kMaxCost for a plane seen edge-on.
MSP_HD float PhotometricViewCost(const PassParams& p, const RefWindow& w, int j,
                                 const PreparedPlane& plane) {
  if (!plane.valid) return kMaxCost;
  const Mat3 H = WarpHomography(p.src[j].rel, plane.warp);
  return WindowNccCost(w, p.ref_image, p.src[j].image, H, p.ncc);
}

// True when view j takes part: its weight is non-zero, or there are no weights.
MSP_HD bool IsWeighted(const float* weights, int j) {
  return weights == nullptr || weights[j] > 0.0f;
}

// The geometric terms of a valid prepared plane in every view that takes
// part (0 for the others). The costs over all views call this before their
// windows, in a loop of its own, so that its reads of the source depth maps,
// which mostly miss the cache, wait together rather than one after each window.
MSP_HD void GeometricTerms(const PassParams& p, int col, int row, const PreparedPlane& plane,
                           const float* weights, float* geometric) {
  for (int j = 0; j < p.num_src; ++j) {
    geometric[j] = IsWeighted(weights, j) ? GeometricTerm(p, j, col, row, plane.depth) : 0.0f;
  }
}

// Costs of h in every view whose weight is non-zero (all views when weights
// is null), kMaxCost in the others: PhotometricViewCost + GeometricTerm of
// each view, the geometric terms first (GeometricTerms).
MSP_HD void ViewCosts(const PassParams& p, const RefWindow& w, const PlaneHypothesis& h,
                      const float* weights, float* costs) {
  const PreparedPlane plane = PreparePlane(p, w.col, w.row, h);
  if (!plane.valid) {
    for (int j = 0; j < p.num_src; ++j) costs[j] = kMaxCost;
    return;
  }
  float geometric[kMaxSourceViews];
  GeometricTerms(p, w.col, w.row, plane, weights, geometric);
  for (int j = 0; j < p.num_src; ++j) {
    costs[j] =
        IsWeighted(weights, j) ? PhotometricViewCost(p, w, j, plane) + geometric[j] : kMaxCost;
  }
}

// Sum of the weights, in AggregateCost's order.
MSP_HD float TotalWeight(const float* weights, int num_views) {
  float w = 0.0f;
  for (int j = 0; j < num_views; ++j) w += weights[j];
  return w;
}

// A limit no cost reaches: the bounded costs below are then exact.
constexpr float kUnboundedCost = 1e30f;

// The weighted mean over the weighted views of photometric(j, plane,
// weight, geometric) + the geometric term of view j, or, as soon as a lower
// bound of it reaches `limit`, that bound instead: a candidate that cannot
// beat `limit` is known to lose before all its windows are scored. The
// bound starts at the geometric terms of all the views (in a geometric pass
// a far-off candidate stops there, with no window scored) and adds each
// view's photometric cost, which must be >= 0, as it is scored. kMaxCost for
// a plane seen edge-on, without a call to `photometric`.
template <typename PhotometricFn>
MSP_HD float BoundedAggregateCost(const PassParams& p, int col, int row, const PlaneHypothesis& h,
                                  const float* weights, float limit, PhotometricFn& photometric) {
  const float total_weight = TotalWeight(weights, p.num_src);
  const PreparedPlane plane = PreparePlane(p, col, row, h);
  if (!plane.valid || !(total_weight > 0.0f)) return kMaxCost;
  float geometric[kMaxSourceViews];
  GeometricTerms(p, col, row, plane, weights, geometric);
  float bound = 0.0f;
  for (int j = 0; j < p.num_src; ++j) bound += weights[j] * geometric[j];
  float sum = 0.0f;
  for (int j = 0; j < p.num_src; ++j) {
    if (!IsWeighted(weights, j)) continue;  // adds weight 0 x kMaxCost = 0
    if (bound / total_weight >= limit) return bound / total_weight;
    const float cost = photometric(j, plane, weights[j], geometric[j]);
    sum += weights[j] * (cost + geometric[j]);
    bound += weights[j] * cost;
  }
  return sum / total_weight;
}

// PhotometricViewCost as the per-view function of BoundedAggregateCost.
struct PhotometricViewCostFn {
  const PassParams& p;
  const RefWindow& w;
  MSP_HD float operator()(int j, const PreparedPlane& plane, float, float) const {
    return PhotometricViewCost(p, w, j, plane);
  }
};

// AggregateCost of ViewCosts(h), or a bound of it at or above `limit`
// (BoundedAggregateCost). (The sums run in AggregateCost's order but may
// round differently from it: compare its results with each other.)
MSP_HD float AggregateViewCostBelow(const PassParams& p, const RefWindow& w,
                                    const PlaneHypothesis& h, const float* weights, float limit) {
  const PhotometricViewCostFn photometric{p, w};
  return BoundedAggregateCost(p, w.col, w.row, h, weights, limit, photometric);
}

static_assert(kNumPropagationCandidates <= kWindowLanes, "one vector lane per candidate");

// Prepares up to kWindowLanes hypotheses h[k] whose `has` is set; returns
// the lanes whose plane is valid.
MSP_HD uint32_t PreparePlanes(const PassParams& p, const RefWindow& w, const PlaneHypothesis* h,
                              const bool* has, int num, PreparedPlane* planes) {
  uint32_t lanes = 0u;
  for (int k = 0; k < num; ++k) {
    if (!has[k]) continue;
    planes[k] = PreparePlane(p, w.col, w.row, h[k]);
    if (planes[k].valid) lanes |= 1u << k;
  }
  return lanes;
}

// GeometricTerms in every view of the prepared planes in `lanes` (up to
// kWindowLanes), geometric[k][j]; with a vector path, one view at a time for
// all of them at once.
MSP_HD void CandidateGeometricTerms(const PassParams& p, int col, int row,
                                    const PreparedPlane* planes, uint32_t lanes, int num,
                                    float (*geometric)[kMaxSourceViews]) {
#if defined(MSP_WINDOW_SUMS_AVX2)
  if (p.geometric) {
    alignas(32) float depth[kWindowLanes];
    for (int k = 0; k < kWindowLanes; ++k) {
      depth[k] = (k < num && ((lanes >> k) & 1u)) ? planes[k].depth : 1.0f;
    }
    for (int j = 0; j < p.num_src; ++j) {
      const SourceView& s = p.src[j];
      alignas(32) float error[kWindowLanes] = {};
      if (s.depth.data != nullptr) {
        _mm256_store_ps(error, ComposedReprojectionErrorLanes(s.rel, s.camera, s.depth, col, row,
                                                              _mm256_load_ps(depth),
                                                              p.geom_max_error, p.geom_depth_unit));
      }
      for (int k = 0; k < num; ++k) geometric[k][j] = p.geom_lambda * error[k];
    }
    return;
  }
#endif
  for (int k = 0; k < num; ++k) {
    if ((lanes >> k) & 1u) GeometricTerms(p, col, row, planes[k], nullptr, geometric[k]);
  }
}

// PreparePlanes, and the geometric terms of the valid planes in every view.
MSP_HD uint32_t PrepareCandidates(const PassParams& p, const RefWindow& w, const PlaneHypothesis* h,
                                  const bool* has, int num, PreparedPlane* planes,
                                  float (*geometric)[kMaxSourceViews]) {
  const uint32_t lanes = PreparePlanes(p, w, h, has, num, planes);
  CandidateGeometricTerms(p, w.col, w.row, planes, lanes, num, geometric);
  return lanes;
}

// The homographies H[k] into source view j of the prepared candidates in
// `lanes`, and the NCC costs of window w under all of them at once.
MSP_HD void CandidateWindowCosts(const PassParams& p, const RefWindow& w, int j,
                                 const PreparedPlane* planes, uint32_t lanes, int num, Mat3* H,
                                 float* ncc) {
  for (int k = 0; k < num; ++k) {
    if ((lanes >> k) & 1u) H[k] = WarpHomography(p.src[j].rel, planes[k].warp);
  }
  WindowNccCosts(w, p.ref_image, p.src[j].image, H, lanes, p.ncc, ncc);
}

// Every view of the pass.
constexpr uint32_t kAllViews = 0xFFFFFFFFu;

// ViewCosts in the views of `views` (bit j = view j) of up to kWindowLanes
// hypotheses h[k] (the rows of `costs`, kMaxSourceViews apart); rows whose
// `has` is false, and views outside `views`, cost kMaxCost. One view at a
// time, the window is scored under all of them at once (WindowNccCosts); the
// geometric terms come first, as in ViewCosts.
MSP_HD void CandidateViewCosts(const PassParams& p, const RefWindow& w, const PlaneHypothesis* h,
                               const bool* has, int num, uint32_t views, float* costs) {
  PreparedPlane planes[kWindowLanes];
  float geometric[kWindowLanes][kMaxSourceViews];
  const uint32_t lanes = PrepareCandidates(p, w, h, has, num, planes, geometric);
  for (int j = 0; j < p.num_src; ++j) {
    if (!((views >> j) & 1u)) {
      for (int k = 0; k < num; ++k) costs[k * kMaxSourceViews + j] = kMaxCost;
      continue;
    }
    Mat3 H[kWindowLanes];
    float ncc[kWindowLanes];
    CandidateWindowCosts(p, w, j, planes, lanes, num, H, ncc);
    for (int k = 0; k < num; ++k) {
      costs[k * kMaxSourceViews + j] = ((lanes >> k) & 1u) ? ncc[k] + geometric[k][j] : kMaxCost;
    }
  }
}

// The view-weighted mean of h's geometric terms (0 in photometric passes, or
// for a plane seen edge-on, whose ViewCosts are kMaxCost without it): the
// aggregate of ViewCosts is that of the PhotometricViewCost of each view plus
// this, so one photometric sweep serves both costs.
MSP_HD float MeanGeometricTerm(const PassParams& p, int col, int row, const PlaneHypothesis& h,
                               const float* weights) {
  if (!p.geometric) return 0.0f;
  const PreparedPlane plane = PreparePlane(p, col, row, h);
  if (!plane.valid) return 0.0f;
  float sum = 0.0f, total_weight = 0.0f;
  for (int j = 0; j < p.num_src; ++j) {
    if (!(weights[j] > 0.0f)) continue;
    sum += weights[j] * GeometricTerm(p, j, col, row, plane.depth);
    total_weight += weights[j];
  }
  return total_weight > 0.0f ? sum / total_weight : 0.0f;
}

// Mean of the k smallest costs (k = kInitialTopViews or fewer views).
MSP_HD float TopViewsCost(const float* costs, int num_views) {
  float best[kInitialTopViews];
  const int k = num_views < kInitialTopViews ? num_views : kInitialTopViews;
  for (int i = 0; i < k; ++i) best[i] = 3.0f * kMaxCost;
  for (int j = 0; j < num_views; ++j) {
    float c = costs[j];
    for (int i = 0; i < k; ++i) {
      if (c < best[i]) {
        const float t = best[i];
        best[i] = c;
        c = t;
      }
    }
  }
  float sum = 0.0f;
  for (int i = 0; i < k; ++i) sum += best[i];
  return k > 0 ? sum / k : kMaxCost;
}

// Random plane for a pixel (round 0 initialisation).
MSP_HD void InitializePixel(const PassParams& p, int col, int row) {
  const int i = p.state.Index(col, row);
  if (IsUnlit(p, i)) {
    ClearPixel(p.state, i);
    return;
  }
  Rng rng = MakeRng(RngKey(p.seed, p.image_id, p.pass_id, 0u, static_cast<uint32_t>(i)));
  p.state.Set(i, RandomHypothesis(p.ref_camera, col, row, p.depth_min, p.depth_max, &rng));
  p.state.mask[i] = 0u;
}

// Recomputes the stored cost of the current plane (after initialisation,
// upsampling, or when a new pass changes the cost function). An unlit pixel
// loses the plane it was carried up with.
MSP_HD void ScorePixel(const PassParams& p, int col, int row) {
  const int i = p.state.Index(col, row);
  if (IsUnlit(p, i)) {
    ClearPixel(p.state, i);
    return;
  }
  const PlaneHypothesis h = p.state.Get(i);
  float costs[kMaxSourceViews];
  if (!(h.depth > 0.0f)) {
    p.state.cost[i] = kMaxCost;
    return;
  }
  RefWindow w;
  PrepareWindow(p, col, row, &w);
  ViewCosts(p, w, h, nullptr, costs);
  p.state.cost[i] = TopViewsCost(costs, p.num_src);
}

// The plane proposed by region `region`: the lowest-cost pixel of the region,
// its plane continued to (col, row). False when the region has no pixel.
MSP_HD bool RegionCandidate(const PassParams& p, int col, int row, int region,
                            PlaneHypothesis* out) {
  const PixelStateView& s = p.state;
  float best = 1e30f;
  int best_col = -1, best_row = -1;
  const int n = RegionSize(region);
  for (int k = 0; k < n; ++k) {
    int dx, dy;
    RegionOffset(region, k, &dx, &dy);
    const int c = col + dx, r = row + dy;
    if (c < 0 || r < 0 || c >= s.width || r >= s.height) continue;
    const int q = s.Index(c, r);
    if (s.depth[q] > 0.0f && s.cost[q] < best) {
      best = s.cost[q];
      best_col = c;
      best_row = r;
    }
  }
  if (best_col < 0) return false;
  const PlaneHypothesis h = s.Get(s.Index(best_col, best_row));
  out->normal = h.normal;
  out->depth = PropagatedDepth(p.ref_camera, best_col, best_row, h, col, row);
  return DepthInRange(p, out->depth) && Dot(out->normal, ViewRay(p.ref_camera, col, row)) < 0.0f;
}

// Refinement hypotheses: mixes of the current, a perturbed and a random depth
// and normal (ACMM).
MSP_HD PlaneHypothesis RefinementCandidate(const PassParams& p, int col, int row,
                                           const PlaneHypothesis& cur, int k, Rng* rng) {
  const Camera& cam = p.ref_camera;
  PlaneHypothesis h = cur;
  const float pert_depth = cur.depth * (1.0f + rng->Uniform(-p.perturb_depth, p.perturb_depth));
  switch (k) {
    case 0:  // perturbed depth and normal
      h.depth = pert_depth;
      h.normal = PerturbNormal(cam, col, row, cur.normal, p.perturb_normal, rng);
      break;
    case 1:  // random depth, current normal
      h.depth = rng->Uniform(p.depth_min, p.depth_max);
      break;
    case 2:  // current depth, random normal
      h.normal = RandomNormal(cam, col, row, rng);
      break;
    case 3:  // perturbed depth, current normal
      h.depth = pert_depth;
      break;
    default:  // current depth, perturbed normal
      h.normal = PerturbNormal(cam, col, row, cur.normal, p.perturb_normal, rng);
      break;
  }
  return h;
}

// One red-black update of pixel (col, row): propagation from the 8 regions
// with view selection, then refinement on the selected views.
MSP_HD void UpdatePixel(const PassParams& p, int col, int row, int iteration) {
  const PixelStateView& s = p.state;
  const int i = s.Index(col, row);
  if (IsUnlit(p, i) || IsHeld(p, i)) return;
  MSP_EVALUATION_PHASE(kPropagationPhase);
  const uint32_t pixel = static_cast<uint32_t>(i);
  constexpr int kRows = kNumPropagationCandidates + 1;  // + the current plane
  PlaneHypothesis cand[kRows];
  bool has[kRows];
  float costs[kNumPropagationCandidates * kMaxSourceViews];
  for (int k = 0; k < kNumPropagationCandidates; ++k) {
    has[k] = RegionCandidate(p, col, row, k, &cand[k]);
  }
  cand[kNumPropagationCandidates] = s.Get(i);
  has[kNumPropagationCandidates] = cand[kNumPropagationCandidates].depth > 0.0f;
  RefWindow w;
  PrepareWindow(p, col, row, &w);
  // The propagated candidates in every view: view selection reads them all.
  // Once the selection has settled, only its views: a view outside it costs
  // kMaxCost, a mismatch that view selection never draws. Where every scored
  // view mismatches, selection falls back to all views, and the next
  // iteration scores all of them again.
  const uint32_t scored = p.weighted_views_only && s.mask[i] != 0u ? s.mask[i] : kAllViews;
  CandidateViewCosts(p, w, cand, has, kNumPropagationCandidates, scored, costs);
  Rng select_rng =
      MakeRng(RngKey(p.seed, p.image_id, p.pass_id, iteration * 4u + kStreamSelect, pixel));
  float weights[kMaxSourceViews];
  const uint32_t mask = SelectViews(costs, kNumPropagationCandidates, p.num_src, kMaxSourceViews,
                                    iteration, s.mask[i], p.num_samples, &select_rng, weights);
  int best = -1;
  float best_cost = 1e30f;
  for (int k = 0; k < kNumPropagationCandidates; ++k) {
    if (!has[k]) continue;
    const float c = AggregateCost(costs + k * kMaxSourceViews, weights, p.num_src);
    if (c < best_cost) {
      best_cost = c;
      best = k;
    }
  }
  // The current plane only competes, last (ties keep the candidate): its
  // selected views suffice, and only until it is known to lose.
  if (has[kNumPropagationCandidates]) {
    const float c =
        AggregateViewCostBelow(p, w, cand[kNumPropagationCandidates], weights, best_cost);
    if (c < best_cost) {
      best_cost = c;
      best = kNumPropagationCandidates;
    }
  }
  PlaneHypothesis cur;
  if (best < 0) {  // nothing valid around and no plane: start afresh
    Rng init_rng =
        MakeRng(RngKey(p.seed, p.image_id, p.pass_id, iteration * 4u + kStreamRestart, pixel));
    cur = RandomHypothesis(p.ref_camera, col, row, p.depth_min, p.depth_max, &init_rng);
    float c[kMaxSourceViews];
    ViewCosts(p, w, cur, weights, c);
    best_cost = AggregateCost(c, weights, p.num_src);
  } else {
    cur = cand[best];
  }
  MSP_EVALUATION_PHASE(kRefinementPhase);
  Rng refine_rng =
      MakeRng(RngKey(p.seed, p.image_id, p.pass_id, iteration * 4u + kStreamRefine, pixel));
  for (int k = 0; k < kNumRefinementCandidates; ++k) {
    const PlaneHypothesis h = RefinementCandidate(p, col, row, cur, k, &refine_rng);
    if (!DepthInRange(p, h.depth)) continue;
    // Most candidates lose, the random ones by far: once a lower bound of
    // their cost reaches best_cost, their remaining views go unscored.
    const float agg = AggregateViewCostBelow(p, w, h, weights, best_cost);
    if (agg < best_cost) {
      best_cost = agg;
      cur = h;
    }
  }
  s.Set(i, cur);
  s.cost[i] = best_cost;
  s.mask[i] = mask;
  MSP_EVALUATION_PHASE(kOtherPhase);
}

}  // namespace core
}  // namespace msp

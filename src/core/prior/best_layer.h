// Best label layer of one unreliable pixel (paper eq. 4): per layer n, the
// anchor subset S_n (segment_crossing.h) is planarised by RANSAC; A_n is its
// inlier count. S_max maximises A_n, ties broken by the larger inlier ratio
// A_n / |S_n|. Host/device neutral; randomness is the counter-based stream.
#pragma once

#include <cstdint>

#include "core/math/hd.h"
#include "core/math/rng.h"
#include "core/math/vec.h"
#include "core/prior/prior_limits.h"
#include "core/prior/segment_crossing.h"

namespace msp {
namespace core {

// Three points span a plane; smaller subsets cannot be planarised (A_n = 0).
constexpr int kMinPlanePoints = 3;
// Sampling stops once a triangle-only-of-inliers has been drawn with this
// probability, given the best inlier ratio so far (adaptive RANSAC); the
// anchors were themselves RANSAC inliers, so most subsets stop early.
constexpr float kRansacConfidence = 0.99f;
// A sample triangle whose sine of the angle at its first vertex is below
// this is treated as collinear (no plane).
constexpr float kCollinearSine = 1e-3f;

// The anchors of one unreliable pixel as plain arrays: pixel positions and
// their camera-frame 3D points (back-projected anchor depths).
struct PriorAnchors {
  int col;  // the unreliable pixel p
  int row;
  int count;  // <= kMaxPriorAnchors
  int cols[kMaxPriorAnchors];
  int rows[kMaxPriorAnchors];
  Vec3 points[kMaxPriorAnchors];
};

struct PlaneRansacParams {
  float inlier_distance;  // point-to-plane distance of an inlier (scene units)
  int iterations;         // sample triangles; all triangles when there are fewer
};

MSP_HD int CountPlaneInliers(const Vec3* points, const int* index, int n, int a, int b, int c,
                             float inlier_distance) {
  const Vec3 pa = points[index[a]];
  const Vec3 u = points[index[b]] - pa;
  const Vec3 v = points[index[c]] - pa;
  const Vec3 normal = Cross(u, v);
  const float area2 = Dot(normal, normal);
  if (!(area2 > kCollinearSine * kCollinearSine * Dot(u, u) * Dot(v, v))) return 0;
  const Vec3 unit = (1.0f / sqrtf(area2)) * normal;
  int inliers = 0;
  for (int i = 0; i < n; ++i) {
    if (fabsf(Dot(unit, points[index[i]] - pa)) <= inlier_distance) ++inliers;
  }
  return inliers;
}

// A_n: the largest inlier count of a plane through three anchors of `subset`.
// Subsets with at most `iterations` triangles are searched exhaustively (exact
// and draw-free); larger ones sample up to `iterations` triangles from
// `rng`, fewer when the best plane so far makes more draws pointless.
MSP_HD int SubsetPlaneInliers(const Vec3* points, uint32_t subset, const PlaneRansacParams& params,
                              Rng rng) {
  int index[kMaxPriorAnchors];
  int n = 0;
  for (int i = 0; i < kMaxPriorAnchors; ++i) {
    if (subset & (1u << i)) index[n++] = i;
  }
  if (n < kMinPlanePoints) return 0;
  int best = 0;
  const int triangles = n * (n - 1) * (n - 2) / 6;
  if (triangles <= params.iterations) {
    for (int a = 0; a < n; ++a) {
      for (int b = a + 1; b < n; ++b) {
        for (int c = b + 1; c < n; ++c) {
          const int count = CountPlaneInliers(points, index, n, a, b, c, params.inlier_distance);
          best = count > best ? count : best;
          if (best == n) return best;  // cannot do better
        }
      }
    }
    return best;
  }
  for (int it = 0; it < params.iterations; ++it) {
    if (best > 0) {
      const float ratio = static_cast<float>(best) / n;
      const float all_inliers = ratio * ratio * ratio;  // P(a triangle of inliers)
      if (all_inliers >= 1.0f || it >= logf(1.0f - kRansacConfidence) / logf(1.0f - all_inliers)) {
        break;
      }
    }
    const int a = static_cast<int>(rng.Uniform() * n) % n;
    const int b = static_cast<int>(rng.Uniform() * n) % n;
    const int c = static_cast<int>(rng.Uniform() * n) % n;
    if (a == b || b == c || a == c) continue;
    const int count = CountPlaneInliers(points, index, n, a, b, c, params.inlier_distance);
    best = count > best ? count : best;
  }
  return best;
}

MSP_HD int PopCount(uint32_t bits) {
  int count = 0;
  for (; bits != 0u; bits &= bits - 1u) ++count;
  return count;
}

// Eq. 4 for one pixel, given its per-layer anchor subsets S_n as bit sets.
// Returns the set of best layers (bit n = layer n is S_max): every layer with
// the largest A_n and, among those, the largest A_n / |S_n|. Layers with equal
// subsets get equal A_n (same random stream), so identical subsets tie and
// all vote. 0 when no layer can be planarised.
MSP_HD uint32_t BestLayers(const PriorAnchors& anchors, const uint32_t* subsets, int num_layers,
                           const PlaneRansacParams& params, Rng rng) {
  int inliers[kMaxLabelLayers];
  for (int n = 0; n < num_layers && n < kMaxLabelLayers; ++n) {
    inliers[n] = -1;
    for (int m = 0; m < n; ++m) {  // reuse the count of an identical subset
      if (subsets[m] == subsets[n]) inliers[n] = inliers[m];
    }
    if (inliers[n] < 0) inliers[n] = SubsetPlaneInliers(anchors.points, subsets[n], params, rng);
  }
  uint32_t best = 0u;
  int best_inliers = 0;
  int best_size = 1;
  for (int n = 0; n < num_layers && n < kMaxLabelLayers; ++n) {
    if (inliers[n] <= 0) continue;
    const int size = PopCount(subsets[n]);
    // Compare (A_n, A_n / |S_n|) lexicographically; ratios by cross-multiplying.
    const long long lhs = static_cast<long long>(inliers[n]) * best_size;
    const long long rhs = static_cast<long long>(best_inliers) * size;
    if (inliers[n] > best_inliers || (inliers[n] == best_inliers && lhs > rhs)) {
      best = 1u << n;
      best_inliers = inliers[n];
      best_size = size;
    } else if (inliers[n] == best_inliers && lhs == rhs) {
      best |= 1u << n;
    }
  }
  return best;
}

// Per-layer subsets and eq. 4 in one call: bit n of `boundaries` is B_n.
MSP_HD uint32_t BestLayersForPixel(const PriorAnchors& anchors, const LayerBoundaryView& boundaries,
                                   int num_layers, const PlaneRansacParams& params, Rng rng) {
  uint32_t subsets[kMaxLabelLayers];
  AdmissibleAnchorsPerLayer(boundaries, num_layers, anchors.col, anchors.row, anchors.cols,
                            anchors.rows, anchors.count, subsets);
  return BestLayers(anchors, subsets, num_layers, params, rng);
}

}  // namespace core
}  // namespace msp
